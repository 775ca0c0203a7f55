//! All conversions between Python objects and core types live here.

use jointplay_core::dynamics::{choose_formulation, ChannelInfo, Formulation, ChannelPeak, Extrema, Model, SimulationOptions, SimulationOutcome, Stabilization};
use jointplay_core::body::BodyKind;
use jointplay_core::joint::MODE_NAMES;
use jointplay_core::modal::FrameReference;
use jointplay_core::integrate::{JacobianMethod, Method};
use jointplay_core::SimulationError;
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

/// Reads simulation options from a dict of plain values (already validated in Python).
pub fn simulation_options(d: &Bound<'_, PyDict>) -> PyResult<SimulationOptions> {
    let mut o = SimulationOptions::default();
    let get = |key: &str| -> PyResult<Option<f64>> { d.get_item(key)?.filter(|v| !v.is_none()).map(|v| v.extract::<f64>()).transpose() };
    if let Some(method) = d.get_item("method")? {
        o.integrator.method = match method.extract::<String>()?.as_str() {
            "dopri5" => Method::DormandPrince45,
            "adams" => Method::AdamsPredictorCorrector,
            "bdf" => Method::NumericalDifferentiation,
            "generalized_alpha" => Method::GeneralizedAlpha,
            other => return Err(PyValueError::new_err(format!("unknown method {other:?}"))),
        };
    }
    if let Some(v) = get("rtol")? {
        o.integrator.rtol = v;
    }
    if let Some(v) = get("atol")? {
        o.integrator.atol = v;
    }
    if let Some(v) = get("max_step")? {
        o.integrator.max_step = v;
    }
    if let Some(v) = get("min_step")? {
        o.integrator.min_step = v;
    }
    o.integrator.initial_step = get("initial_step")?;
    o.integrator.output_step = get("output_step")?;
    o.integrator.step = get("step")?;
    if let Some(v) = get("spectral_radius")? {
        o.integrator.spectral_radius = v;
    }
    if let Some(v) = d.get_item("max_steps")?.filter(|v| !v.is_none()) {
        o.integrator.max_steps = v.extract()?;
    }
    if let Some(v) = d.get_item("max_order")?.filter(|v| !v.is_none()) {
        o.integrator.max_order = v.extract()?;
    }
    if let Some(s) = d.get_item("jacobian")?.filter(|v| !v.is_none()) {
        o.integrator.jacobian = match s.extract::<String>()?.as_str() {
            "auto" => JacobianMethod::Auto,
            "finite_difference" => JacobianMethod::FiniteDifference,
            "structured" => JacobianMethod::Structured,
            other => return Err(PyValueError::new_err(format!("unknown jacobian {other:?}"))),
        };
    }
    if let Some(v) = d.get_item("max_output_bytes")?.filter(|v| !v.is_none()) {
        o.max_output_bytes = Some(v.extract()?);
    }
    if let Some(v) = get("position_tolerance")? {
        o.position_tolerance = Some(v);
    }
    if let Some(s) = d.get_item("stabilization")? {
        o.stabilization = match s.extract::<String>()?.as_str() {
            "projection" => Stabilization::Projection,
            "baumgarte" => Stabilization::Baumgarte { alpha: get("baumgarte_alpha")?.unwrap_or(10.0), beta: get("baumgarte_beta")?.unwrap_or(10.0) },
            "none" => Stabilization::None,
            other => return Err(PyValueError::new_err(format!("unknown stabilization {other:?}"))),
        };
    }
    if let Some(s) = d.get_item("formulation")?.filter(|v| !v.is_none()) {
        o.formulation = match s.extract::<String>()?.as_str() {
            "auto" => Formulation::Auto,
            "absolute" => Formulation::Absolute,
            "joint_coordinates" => Formulation::JointCoordinates,
            other => return Err(PyValueError::new_err(format!("unknown formulation {other:?}"))),
        };
    }
    o.integrator.validate().map_err(PyValueError::new_err)?;
    Ok(o)
}

/// A simulation error as a dict: kind, message, time, element.
pub fn simulation_error<'py>(py: Python<'py>, e: &SimulationError) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let kind = format!("{e:?}");
    d.set_item("kind", kind.split([' ', '{', '(']).next().unwrap_or(""))?;
    d.set_item("message", e.to_string())?;
    d.set_item("time", e.time())?;
    d.set_item("element", e.element())?;
    Ok(d)
}

/// Notes of an assembly as a list of `(name, on_body, message)`.
pub fn assembly_notes<'py>(py: Python<'py>, notes: &[jointplay_core::dynamics::AssemblyNote]) -> PyResult<Bound<'py, PyList>> {
    PyList::new(py, notes.iter().map(|n| (n.name.as_str(), n.on_body, n.message.as_str())))
}

/// Channel names, units and descriptions into `out`.
pub fn channel_infos(py: Python<'_>, out: &Bound<'_, PyDict>, infos: &[ChannelInfo]) -> PyResult<()> {
    out.set_item("names", PyList::new(py, infos.iter().map(|c| c.name.as_str()))?)?;
    out.set_item("units", PyList::new(py, infos.iter().map(|c| c.unit))?)?;
    out.set_item("descriptions", PyList::new(py, infos.iter().map(|c| c.description.as_str()))?)?;
    Ok(())
}

/// A simulation outcome into `out` (its recorded values handed over without a copy).
pub fn outcome(py: Python<'_>, out: &Bound<'_, PyDict>, mut o: SimulationOutcome) -> PyResult<()> {
    // (with a sink, only the samples not handed over: none at the end of a run)
    let shape = [o.trajectory.len(), o.trajectory.channels.len()];
    let (time, samples) = o.trajectory.take();
    out.set_item("time", PyArray1::from_vec(py, time))?;
    // (samples, channels) as recorded; Python keeps it and reads a channel as a column
    out.set_item("values", PyArray1::from_vec(py, samples).reshape(shape)?)?;
    channel_infos(py, out, &o.trajectory.channels)?;
    let s = &o.statistics;
    let stats = PyDict::new(py);
    stats.set_item("accepted_steps", s.accepted_steps)?;
    stats.set_item("rejected_steps", s.rejected_steps)?;
    stats.set_item("rhs_evaluations", s.rhs_evaluations)?;
    stats.set_item("events", s.events)?;
    stats.set_item("smallest_step", s.smallest_step)?;
    stats.set_item("largest_step", s.largest_step)?;
    stats.set_item("restarts", s.restarts)?;
    stats.set_item("jacobian_evaluations", s.jacobian_evaluations)?;
    stats.set_item("jacobian_rhs_evaluations", s.jacobian_rhs_evaluations)?;
    stats.set_item("jacobian_force_evaluations", s.jacobian_force_evaluations)?;
    stats.set_item("factorizations", s.factorizations)?;
    stats.set_item("sparse_factorizations", s.sparse_factorizations)?;
    stats.set_item("formulation", o.formulation.name())?;
    stats.set_item("formulation_reason", &o.formulation_reason)?;
    out.set_item("statistics", stats)?;
    let g = &o.diagnostics;
    let diag = PyDict::new(py);
    diag.set_item("max_penetration", g.max_penetration)?;
    diag.set_item("deep_penetration_steps", g.deep_penetration_steps)?;
    diag.set_item("max_projection_iterations", g.max_projection_iterations)?;
    diag.set_item("max_projection_residual", g.max_projection_residual)?;
    diag.set_item("max_projection_residual_time", g.max_projection_residual_time)?;
    diag.set_item("projection_tolerance", g.projection_tolerance)?;
    diag.set_item("impacts", g.impacts.clone())?;
    out.set_item("diagnostics", diag)?;
    out.set_item("extrema", extrema(py, &o.extrema)?)?;
    match &o.error {
        Some(e) => out.set_item("error", simulation_error(py, e)?)?,
        None => out.set_item("error", py.None())?,
    }
    out.set_item("stage", "integration")?;
    Ok(())
}

/// The summary tracked at every accepted step as plain data (JSON-serialisable:
/// a time or extremum that does not exist, such as the time of a penetration
/// never reached or anything of a run without a step, is None):
/// `{"steps", "inner_evaluations", "fallback_searches", "t_start", "t_end", "channels": {name: {"peak", "value", "time", "unit"}},
/// "point_accelerations": {"<body>.<point>": {"peak", "time", "unit"}},
/// "clearance_joints": {name: {"impacts", "contact_time", "contact_fraction",
/// "max_penetration", "max_penetration_time", "max_eccentricity_ratio", and for lubricated joints "min_film",
/// "min_film_time", "peak_film_pressure", "peak_film_pressure_time", for spatial clearance joints
/// "mode_fractions": {"free", "impact", "sliding", "sustained", "axial"}}}}`.
pub fn extrema<'py>(py: Python<'py>, e: &Extrema) -> PyResult<Bound<'py, PyDict>> {
    let finite = |x: f64| if x.is_finite() { Some(x) } else { None };
    let d = PyDict::new(py);
    d.set_item("steps", e.steps)?;
    d.set_item("inner_evaluations", e.inner_evaluations)?;
    d.set_item("fallback_searches", e.fallback_searches)?;
    d.set_item("t_start", finite(e.t_start))?;
    d.set_item("t_end", finite(e.t_end))?;
    d.set_item("channels", peaks(py, &e.channels, true)?)?;
    d.set_item("point_accelerations", peaks(py, &e.point_accelerations, false)?)?;
    let joints = PyDict::new(py);
    for j in &e.clearance_joints {
        let entry = PyDict::new(py);
        entry.set_item("impacts", j.impacts)?;
        entry.set_item("contact_time", j.contact_time)?;
        entry.set_item("contact_fraction", j.contact_fraction)?;
        entry.set_item("max_penetration", j.max_penetration)?;
        entry.set_item("max_penetration_time", finite(j.max_penetration_time))?;
        entry.set_item("max_eccentricity_ratio", finite(j.max_eccentricity_ratio))?;
        if let (Some(film), Some(at)) = (j.min_film, j.min_film_time) {
            entry.set_item("min_film", finite(film))?;
            entry.set_item("min_film_time", finite(at))?;
        }
        if let Some((pressure, at)) = j.peak_film_pressure {
            entry.set_item("peak_film_pressure", pressure)?;
            entry.set_item("peak_film_pressure_time", finite(at))?;
        }
        if let Some(fractions) = j.mode_fractions {
            let modes = PyDict::new(py);
            for (mode, fraction) in MODE_NAMES.iter().zip(fractions) {
                modes.set_item(mode, fraction)?;
            }
            entry.set_item("mode_fractions", modes)?;
        }
        joints.set_item(&j.name, entry)?;
    }
    d.set_item("clearance_joints", joints)?;
    Ok(d)
}

/// Peaks by name: `{name: {"peak", "time", "unit"}}`, with the signed `"value"` when `with_value`.
fn peaks<'py>(py: Python<'py>, peaks: &[ChannelPeak], with_value: bool) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    for c in peaks {
        let entry = PyDict::new(py);
        entry.set_item("peak", c.peak)?;
        if with_value {
            entry.set_item("value", c.value)?;
        }
        entry.set_item("time", c.time)?;
        entry.set_item("unit", c.unit)?;
        out.set_item(&c.name, entry)?;
    }
    Ok(out)
}

/// Summary of a compiled model.
pub fn describe<'py>(py: Python<'py>, m: &Model) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("name", &m.name)?;
    let bodies = PyList::empty(py);
    for (b, address) in m.bodies.iter().zip(&m.layout.bodies) {
        let e = PyDict::new(py);
        e.set_item("name", &b.name)?;
        e.set_item("coordinates", (address.q, address.nq))?;
        match &b.kind {
            BodyKind::PlanarRigid(rigid) => {
                e.set_item("kind", "planar_rigid")?;
                e.set_item("mass", rigid.mass)?;
                e.set_item("inertia", rigid.inertia)?;
            }
            BodyKind::Beam(beam) => {
                let section = &beam.elements[0].section;
                e.set_item("kind", "beam")?;
                e.set_item("mass", beam.mass())?;
                e.set_item("length", beam.length)?;
                e.set_item("elements", beam.elements.len())?;
                e.set_item("order", format!("{:?}", beam.elements[0].order).to_lowercase())?;
                e.set_item("nodes", beam.n_nodes())?;
                e.set_item("axial_stiffness", section.axial_stiffness)?;
                e.set_item("shear_stiffness", section.shear_stiffness)?;
                e.set_item("bending_stiffness", section.bending_stiffness)?;
                e.set_item("damping_time", beam.damping_time)?;
            }
            BodyKind::Modal(modal) => {
                e.set_item("kind", "modal")?;
                e.set_item("mass", modal.mass())?;
                e.set_item("modes", modal.n_modes())?;
                e.set_item("nodes", modal.n_nodes())?;
                e.set_item("interface_nodes", modal.interface().to_vec())?;
                e.set_item("frame", match modal.frame_reference() {
                    FrameReference::Chord => "chord",
                    FrameReference::Clamped => "clamped",
                })?;
                e.set_item("damping_ratio", modal.damping_ratio())?;
                e.set_item("damping_time", modal.retardation_time())?;
                e.set_item("first_bending_frequency", modal.first_bending_frequency())?;
                let held: Vec<f64> = modal.held_frequencies().iter().map(|w| w / std::f64::consts::TAU).collect();
                e.set_item("held_frequencies", held)?;
            }
            BodyKind::SpatialRigid(rigid) => {
                e.set_item("kind", "spatial_rigid")?;
                e.set_item("mass", rigid.mass)?;
                let inertia: Vec<Vec<f64>> = (0..3).map(|i| (0..3).map(|j| rigid.inertia[(i, j)]).collect()).collect();
                e.set_item("inertia", inertia)?;
                e.set_item("euler_sequence", rigid.euler_sequence.name())?;
            }
        }
        bodies.append(e)?;
    }
    d.set_item("bodies", bodies)?;
    let elements = PyList::empty(py);
    for (k, el) in m.ideal_elements() {
        let e = PyDict::new(py);
        e.set_item("name", &m.elements[k].name)?;
        e.set_item("kind", format!("{:?}", el.kind))?;
        e.set_item("first", m.body_name(el.first))?;
        e.set_item("second", m.body_name(el.second))?;
        let rows: usize = el.constraints.clone().map(|k| m.row_offsets[k + 1] - m.row_offsets[k]).sum();
        e.set_item("equations", rows)?;
        elements.append(e)?;
    }
    d.set_item("elements", elements)?;
    let clearance: Vec<&str> = m.clearance_joints().map(|(_, name, _)| name).collect();
    let forces: Vec<&str> = m.acting.iter().map(|&k| m.elements[k].name.as_str()).filter(|name| !clearance.contains(name)).collect();
    d.set_item("clearance_joints", clearance)?;
    d.set_item("forces", forces)?;
    d.set_item("n_coordinates", m.n_velocities())?;
    d.set_item("n_element_states", m.layout.nz)?;
    d.set_item("n_equations", m.n_dynamic_equations())?;
    d.set_item("degrees_of_freedom", m.degrees_of_freedom())?;
    match &m.joint_tree {
        Ok(tree) => {
            d.set_item("joint_coordinates", tree.n_dofs)?;
            d.set_item("absolute_because", py.None())?;
        }
        Err(why) => {
            d.set_item("joint_coordinates", py.None())?;
            d.set_item("absolute_because", why)?;
        }
    }
    // what `auto` chooses, and why (the rule of the core, written once there)
    let auto = choose_formulation(m, Formulation::Auto).map_err(PyValueError::new_err)?;
    d.set_item("formulation", auto.formulation.name())?;
    d.set_item("formulation_reason", auto.reason)?;
    channel_infos(py, &d, &m.channel_infos())?;
    Ok(d)
}
