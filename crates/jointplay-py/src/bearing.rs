//! Journal-bearing tools for Python: one Reynolds solve (pressure field and
//! outputs) and the steady Raimondi-Boyd analysis. Arguments are plain SI
//! numbers; errors come back as `ValueError` with the core's message.

use jointplay_core::lubrication::reynolds::{Cavitation, Groove, ReynoldsOptions, ReynoldsSolver, MAX_GRID_NODES, MAX_TABLE_NODES};
use jointplay_core::lubrication::steady::{self, SteadyBearing};
use jointplay_core::lubrication::{BearingGeometry, FilmKinematics};
use numpy::PyArray1;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::{guarded, signal_watch};
use pyo3::exceptions::PyKeyboardInterrupt;

/// Runs `f` with the GIL released, letting pending signals run about every [`crate::WATCH_INTERVAL`]
/// from inside its Reynolds sweeps: Ctrl-C stops a long solve at once (`KeyboardInterrupt`).
fn interruptible<T: Send>(py: Python<'_>, f: impl FnOnce() -> Result<T, String> + Send) -> PyResult<T> {
    let progress = signal_watch();
    let run = py.detach(|| progress.scope(|| guarded(f)))?;
    if progress.is_cancelled() {
        return Err(PyKeyboardInterrupt::new_err("Reynolds solve interrupted"));
    }
    run.map_err(PyValueError::new_err)
}

/// Module constants: the size bounds of the core, so that Python checks its
/// options against the same numbers.
pub fn add_constants(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("MAX_REYNOLDS_GRID_NODES", MAX_GRID_NODES)?;
    m.add("MAX_FORCE_TABLE_NODES", MAX_TABLE_NODES)?;
    Ok(())
}

/// Solver options from the Python arguments.
fn options(n_circumferential: usize, n_axial: usize, cavitation: &str, tolerance: f64, max_iterations: usize) -> PyResult<ReynoldsOptions> {
    let cavitation = match cavitation {
        "gumbel" => Cavitation::Gumbel,
        "swift_stieber" => Cavitation::SwiftStieber,
        "elrod_adams" => Cavitation::ElrodAdams,
        other => {
            return Err(PyValueError::new_err(format!(
                "cavitation must be 'gumbel', 'swift_stieber' or 'elrod_adams', got {other:?}"
            )))
        }
    };
    Ok(ReynoldsOptions { n_circumferential, n_axial, cavitation, tolerance, max_iterations, ..Default::default() })
}

/// One Reynolds solve; returns outputs, the pressure and fill fields (flat,
/// `n_theta x n_half`, see `theta` and `z`) and the field shape.
#[pyfunction]
#[pyo3(signature = (radius, length, clearance, viscosity, eccentricity, eccentricity_rate, journal_spin, bearing_spin,
    n_circumferential=120, n_axial=16, cavitation="swift_stieber", ambient_pressure=0.0, supply_pressure=None,
    groove_width=0.0, feed_at_thickest_film=false, tolerance=1e-7, max_iterations=20000))]
#[allow(clippy::too_many_arguments)]
pub fn reynolds_solve<'py>(
    py: Python<'py>, radius: f64, length: f64, clearance: f64, viscosity: f64, eccentricity: (f64, f64),
    eccentricity_rate: (f64, f64), journal_spin: f64, bearing_spin: f64, n_circumferential: usize, n_axial: usize,
    cavitation: &str, ambient_pressure: f64, supply_pressure: Option<f64>, groove_width: f64, feed_at_thickest_film: bool,
    tolerance: f64, max_iterations: usize,
) -> PyResult<Bound<'py, PyDict>> {
    let mut o = options(n_circumferential, n_axial, cavitation, tolerance, max_iterations)?;
    o.ambient_pressure = ambient_pressure;
    o.groove = supply_pressure.map(|p| Groove { supply_pressure: p, width: groove_width });
    o.feed_at_thickest_film = feed_at_thickest_film;
    let geometry = BearingGeometry { radius, length, clearance, viscosity };
    let kin = FilmKinematics {
        eccentricity: [eccentricity.0, eccentricity.1].into(),
        eccentricity_rate: [eccentricity_rate.0, eccentricity_rate.1].into(),
        journal_spin,
        bearing_spin,
    };
    let (solver, sol) = interruptible(py, || {
        let mut solver = ReynoldsSolver::new(geometry, o)?;
        let sol = solver.solve(&kin)?;
        Ok::<_, String>((solver, sol))
    })?;
    let (n_theta, n_half) = solver.field_shape();
    let d = PyDict::new(py);
    d.set_item("force_on_journal", (sol.force_on_journal.x, sol.force_on_journal.y))?;
    for (k, v) in [
        ("peak_pressure", sol.peak_pressure), ("peak_pressure_angle", sol.peak_pressure_angle),
        ("min_film_thickness", sol.min_film_thickness), ("eccentricity_ratio", sol.eccentricity_ratio),
        ("attitude_angle", sol.attitude_angle), ("friction_torque", sol.friction_torque),
        ("bearing_friction_torque", sol.bearing_friction_torque), ("power_loss", sol.power_loss),
        ("side_leakage", sol.side_leakage), ("groove_inflow", sol.groove_inflow),
        ("circumferential_flow", sol.circumferential_flow),
        ("complementarity_residual", solver.complementarity_residual()),
    ] {
        d.set_item(k, v)?;
    }
    d.set_item("iterations", sol.iterations)?;
    d.set_item("shape", (n_theta, n_half))?;
    d.set_item("pressure", PyArray1::from_slice(py, solver.pressure()))?;
    d.set_item("fill_fraction", PyArray1::from_slice(py, solver.fill_fraction()))?;
    let theta: Vec<f64> = (0..n_theta).map(|i| i as f64 * 2.0 * std::f64::consts::PI / n_theta as f64).collect();
    let z: Vec<f64> = (0..n_half).map(|j| solver.axial_position(j)).collect();
    d.set_item("theta", PyArray1::from_vec(py, theta))?;
    d.set_item("z", PyArray1::from_vec(py, z))?;
    Ok(d)
}

/// Steady bearing (Raimondi-Boyd variables) by eccentricity ratio, or by load
/// with geometry, viscosity and speed [rev/s]; dimensional outputs when the geometry is given.
#[pyfunction]
#[pyo3(signature = (length_over_diameter, eccentricity_ratio=None, load=None, radius=None, clearance=None,
    viscosity=None, speed=None, n_circumferential=120, n_axial=16, tolerance=1e-7))]
#[allow(clippy::too_many_arguments)]
pub fn steady_bearing<'py>(
    py: Python<'py>, length_over_diameter: f64, eccentricity_ratio: Option<f64>, load: Option<f64>, radius: Option<f64>,
    clearance: Option<f64>, viscosity: Option<f64>, speed: Option<f64>, n_circumferential: usize, n_axial: usize,
    tolerance: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let o = options(n_circumferential, n_axial, "swift_stieber", tolerance, 20_000)?;
    let geometry = match (radius, clearance, viscosity) {
        (Some(r), Some(c), Some(mu)) => Some(BearingGeometry { radius: r, length: 2.0 * r * length_over_diameter, clearance: c, viscosity: mu }),
        _ => None,
    };
    let point = interruptible(py, || match (eccentricity_ratio, load, geometry, speed) {
        (Some(eps), None, _, _) => steady::steady_at_eccentricity(length_over_diameter, eps, &o),
        (None, Some(w), Some(g), Some(n)) => steady::steady_for_load(w, &g, n, &o),
        _ => Err("give either eccentricity_ratio, or load with radius, clearance, viscosity and speed".to_string()),
    })?;
    let d = PyDict::new(py);
    put_point(&d, &point)?;
    if let (Some(g), Some(n)) = (geometry, speed) {
        let dim = point.dimensional(&g, n);
        for (k, v) in [
            ("load", dim.load), ("mean_pressure", dim.mean_pressure), ("min_film_thickness", dim.min_film_thickness),
            ("peak_pressure", dim.peak_pressure), ("friction_torque", dim.friction_torque),
            ("friction_coefficient", dim.friction_coefficient), ("power_loss", dim.power_loss),
            ("flow", dim.flow), ("side_flow", dim.side_flow),
        ] {
            d.set_item(k, v)?;
        }
    }
    Ok(d)
}

/// The dimensionless fields of a steady point into `d`.
fn put_point(d: &Bound<'_, PyDict>, p: &SteadyBearing) -> PyResult<()> {
    for (k, v) in [
        ("length_over_diameter", p.length_over_diameter), ("eccentricity_ratio", p.eccentricity_ratio),
        ("attitude_angle", p.attitude_angle), ("sommerfeld_number", p.sommerfeld_number),
        ("min_film_thickness_ratio", p.min_film_thickness_ratio), ("friction_variable", p.friction_variable),
        ("flow_variable", p.flow_variable), ("side_flow_ratio", p.side_flow_ratio),
        ("pressure_ratio", p.pressure_ratio), ("peak_pressure_angle", p.peak_pressure_angle),
    ] {
        d.set_item(k, v)?;
    }
    Ok(())
}
