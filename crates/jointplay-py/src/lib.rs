//! Python bindings of jointplay: a thin layer that hands plain data between
//! Python and [`jointplay_core`]. Errors come back as data; the Python
//! package raises its own exception types from them.

mod bearing;
mod conv;
mod spec_json;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::{Arc, Mutex};
use std::time::Duration;

use jointplay_core::dynamics::{self, Model, Progress, SampleSink, Workspace};
use jointplay_core::spec::ModelSpec;
use numpy::{PyArray1, PyArray2, PyArrayMethods};
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// Runs `f`, turning a Rust panic into a Python `RuntimeError` naming it an internal error.
fn guarded<T>(f: impl FnOnce() -> T) -> PyResult<T> {
    catch_unwind(AssertUnwindSafe(f)).map_err(|payload| {
        let detail = payload
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        PyRuntimeError::new_err(format!("internal error in the jointplay core (please report it): {detail}"))
    })
}

/// A compiled mechanism.
#[pyclass(frozen, module = "jointplay._core")]
struct CoreModel {
    model: Arc<Model>,
}

/// Wall time between two calls back from a running simulation (progress, signals).
pub(crate) const WATCH_INTERVAL: Duration = Duration::from_millis(100);

/// A watcher for a long call outside a simulation (a force table, a bearing solve): every
/// [`WATCH_INTERVAL`] it lets pending signals run, and Ctrl-C cancels it.
pub(crate) fn signal_watch() -> Progress {
    Progress::watched(WATCH_INTERVAL, |_| Python::attach(|py| py.check_signals().is_ok()))
}

/// One call back from a running simulation (GIL held): `progress(t)`, then pending signals.
/// False stops the run; an exception other than `KeyboardInterrupt` is kept in `raised`
/// (an interrupt becomes the run's `Interrupted` error, with the results kept).
fn poll(py: Python<'_>, progress: Option<&Py<PyAny>>, t: f64, raised: &Mutex<Option<PyErr>>) -> bool {
    let called = progress.map_or(Ok(()), |callback| callback.call1(py, (t,)).map(drop));
    match called.and_then(|()| py.check_signals()) {
        Ok(()) => true,
        Err(error) => {
            if !error.is_instance_of::<PyKeyboardInterrupt>(py) {
                if let Ok(mut slot) = raised.lock() {
                    slot.get_or_insert(error);
                }
            }
            false
        }
    }
}

/// A Python callable `sink(times, values, start)` receiving the samples chunk by chunk (GIL
/// taken back for each call): `times` of shape (n,), `values` of shape (n, channels), `start` the
/// index of the first sample. An exception it raises is kept in `raised` (to be raised once the run
/// has stopped) and stops the run, except a Ctrl-C (`KeyboardInterrupt`): the chunk is then handed
/// over again with the same `start` (the sink takes it once) and the run is cancelled, so that it
/// stops at its next sample as `Interrupted`, with everything computed kept.
struct PythonSink {
    callable: Py<PyAny>,
    channels: usize,
    raised: Arc<Mutex<Option<PyErr>>>,
    /// Samples handed over so far.
    handed: usize,
    /// The run's progress, cancelled by a Ctrl-C inside the sink.
    progress: Arc<Progress>,
}

/// Times a chunk is handed over again after Ctrl-C interrupted the call (a user pressing Ctrl-C
/// repeatedly then stops the run with what was written).
const INTERRUPTED_HANDOVERS: usize = 3;

impl SampleSink for PythonSink {
    fn write_chunk(&mut self, times: &[f64], rows: &[f64]) -> Result<(), String> {
        Python::attach(|py| {
            let mut interrupted = false;
            for _ in 0..=INTERRUPTED_HANDOVERS {
                let called = PyArray1::from_slice(py, rows).reshape([times.len(), self.channels]).and_then(|values| {
                    self.callable.call1(py, (PyArray1::from_slice(py, times), values, self.handed))
                });
                match called {
                    Ok(_) => {
                        self.handed += times.len();
                        if interrupted {
                            self.progress.cancel();
                        }
                        return Ok(());
                    }
                    Err(error) if error.is_instance_of::<PyKeyboardInterrupt>(py) => interrupted = true,
                    Err(error) => {
                        let message = error.to_string();
                        if let Ok(mut slot) = self.raised.lock() {
                            slot.get_or_insert(error);
                        }
                        return Err(message);
                    }
                }
            }
            Err("interrupted (Ctrl-C) while handing the samples to the results file".to_string())
        })
    }
}

/// Compiles a JSON model description. Returns `(model, None)` or `(None, [(location, message), ...])`;
/// a description that cannot be read (a missing key, say: the spec has no defaults) is such a list too,
/// each problem at its element (`joints[2]`).
#[pyfunction]
fn compile_model(py: Python<'_>, spec_json: &str) -> PyResult<(Option<CoreModel>, Option<Vec<(String, String)>>)> {
    let spec: ModelSpec = match spec_json::read_spec(spec_json) {
        Ok(spec) => spec,
        Err(problems) => return Ok((None, Some(problems))),
    };
    // (a force table is built here: thousands of Reynolds solves, which Ctrl-C stops from inside)
    let progress = signal_watch();
    let compiled = py.detach(|| progress.scope(|| guarded(|| dynamics::compile(&spec))))?;
    if progress.is_cancelled() {
        return Err(PyKeyboardInterrupt::new_err("compilation interrupted"));
    }
    Ok(match compiled {
        Ok(model) => (Some(CoreModel { model: Arc::new(model) }), None),
        Err(errors) => (None, Some(errors.0.into_iter().map(|e| (e.location, e.message)).collect())),
    })
}

/// The keys of every table of the model description as the core reads them: `(table, [(key, optional)])`,
/// tables named `"bodies"`, `"forces.spring_damper"`, `"contact.flores"` (`jointplay_core::spec::table_keys`).
#[pyfunction]
fn spec_tables() -> PyResult<Vec<(String, Vec<(String, bool)>)>> {
    let tables = jointplay_core::spec::table_keys().map_err(pyo3::exceptions::PyRuntimeError::new_err)?;
    Ok(tables.into_iter().map(|(table, keys)| (table, keys.into_iter().map(|k| (k.key, k.optional)).collect())).collect())
}

#[pymethods]
impl CoreModel {
    /// Summary of the compiled mechanism (bodies, elements, coordinates, dof, channels).
    fn describe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        conv::describe(py, &self.model)
    }

    /// Natural frequencies [Hz] of each beam, unstressed: `{name: (free-free, clamped at its start)}`,
    /// `count` of each; a beam with more than `max_coordinates` coordinates is left out (a dense eigensolve).
    fn beam_frequencies<'py>(&self, py: Python<'py>, count: usize, max_coordinates: usize) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for body in &self.model.bodies {
            if let jointplay_core::body::BodyKind::Beam(beam) = &body.kind {
                if beam.n_coordinates() <= max_coordinates {
                    let frequencies = guarded(|| beam.natural_frequencies(count))?.map_err(PyRuntimeError::new_err)?;
                    out.set_item(&body.name, frequencies)?;
                }
            }
        }
        Ok(out)
    }

    /// The first bending frequency [Hz] of each modal body (clamped at its frame node): `{name: f1}`.
    /// A linear modal body spun faster than `2 pi f1` diverges (no geometric stiffening).
    fn modal_bending_frequencies<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let out = PyDict::new(py);
        for (name, frequency) in self.model.modal_bending_frequencies() {
            out.set_item(name, frequency)?;
        }
        Ok(out)
    }

    /// What a drawing of the mechanism needs beyond the model and the channels:
    /// `{"modal_bodies": {name: {"nodes": [[x, y], ...], "shapes": [[[dx per mode], [dy per mode]], ...],
    /// "edges": [[a, b], ...]}}}`: each modal body's reference nodes in its frame [m], their translations per
    /// unit amplitude of each mode in the frame [m per unit], and the mesh's lines.
    fn drawing_geometry<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let modal = PyDict::new(py);
        for body in &self.model.bodies {
            if let jointplay_core::body::BodyKind::Modal(modal_body) = &body.kind {
                let n = modal_body.n_nodes();
                let nodes: Vec<[f64; 2]> = (0..n).map(|a| modal_body.node_position(a)).map(|p| [p.x, p.y]).collect();
                let shapes: Vec<[Vec<f64>; 2]> = (0..n).map(|a| modal_body.node_mode_translations(a)).map(|(x, y)| [x.to_vec(), y.to_vec()]).collect();
                let entry = PyDict::new(py);
                entry.set_item("nodes", nodes)?;
                entry.set_item("shapes", shapes)?;
                entry.set_item("edges", modal_body.edges().to_vec())?;
                modal.set_item(&body.name, entry)?;
            }
        }
        let out = PyDict::new(py);
        out.set_item("modal_bodies", modal)?;
        Ok(out)
    }

    /// Consistent initial coordinates and velocities at `t0`, or an error record.
    fn assemble<'py>(&self, py: Python<'py>, t0: f64) -> PyResult<Bound<'py, PyDict>> {
        let model = Arc::clone(&self.model);
        let result = py.detach(move || {
            guarded(|| {
                let mut ws = Workspace::new(&model);
                dynamics::assemble(&model, t0, &mut ws).map(|state| {
                    let notes = dynamics::assembly_notes(&model, t0, state.coordinates(), &mut ws);
                    let rank = dynamics::constraint_rank(&model, &state, &mut ws);
                    (state, rank, notes)
                })
            })
        })?;
        let out = PyDict::new(py);
        match result {
            Ok((state, rank, notes)) => {
                out.set_item("notes", conv::assembly_notes(py, &notes)?)?;
                out.set_item("coordinates", PyArray1::from_slice(py, state.coordinates()))?;
                out.set_item("velocities", PyArray1::from_slice(py, state.velocities()))?;
                out.set_item("constraint_rank", rank.rank)?;
                out.set_item("redundant_equations", rank.n_redundant())?;
                out.set_item("dependent_elements", rank.dependent_elements.clone())?;
                out.set_item("error", py.None())?;
            }
            Err(e) => out.set_item("error", conv::simulation_error(py, &e)?)?,
        }
        Ok(out)
    }

    /// The static equilibrium at `t0` (drivers held), or an error record.
    fn equilibrium<'py>(&self, py: Python<'py>, t0: f64, force_tolerance: f64, max_iterations: usize) -> PyResult<Bound<'py, PyDict>> {
        let model = Arc::clone(&self.model);
        let options = dynamics::EquilibriumOptions { force_tolerance, max_iterations, ..Default::default() };
        let raised = Arc::new(Mutex::new(None));
        let watched = {
            let raised = Arc::clone(&raised);
            Progress::watched(WATCH_INTERVAL, move |t| Python::attach(|py| poll(py, None, t, &raised)))
        };
        let result = py.detach(move || guarded(|| watched.scope(|| dynamics::equilibrium(&model, t0, &options, &mut Workspace::new(&model)))))?;
        if let Some(error) = raised.lock().map_err(|_| PyRuntimeError::new_err("callback state poisoned"))?.take() {
            return Err(error);
        }
        let out = PyDict::new(py);
        match result {
            Ok(found) => {
                out.set_item("coordinates", PyArray1::from_slice(py, found.state.coordinates()))?;
                out.set_item("element_states", PyArray1::from_slice(py, self.model.layout.split(&found.state.y).2))?;
                out.set_item("force_residual", found.force_residual)?;
                out.set_item("constraint_residual", found.constraint_residual)?;
                out.set_item("iterations", found.iterations)?;
                out.set_item("error", py.None())?;
            }
            Err(e) => out.set_item("error", conv::simulation_error(py, &e)?)?,
        }
        Ok(out)
    }

    /// Assembles at `t0` and simulates to `t_end` in the calling thread with the GIL released.
    /// About every [`WATCH_INTERVAL`] the core takes the GIL back for a moment: it calls
    /// `progress(t)` (if given) and lets pending signals run, so that Ctrl-C stops the run within
    /// about that interval (its check is reached from every evaluation and every Reynolds sweep),
    /// with what was computed kept. An exception raised by `progress` also
    /// stops the run and is raised here. With `sink`, the samples go to `sink(times, values, start)`
    /// in chunks of about 4 MiB while the run goes on (see [`PythonSink`]) and the returned
    /// `time` and `values` are empty; an exception in `sink` stops the run and is raised here.
    /// With `from_equilibrium` the run starts at rest in the static equilibrium at `t0`; with
    /// `initial_state` (`[q, v, z]` as the layout orders them) it starts there as given.
    #[pyo3(signature = (t0, t_end, options, progress=None, sink=None, from_equilibrium=false, initial_state=None))]
    #[allow(clippy::too_many_arguments)]
    fn simulate<'py>(
        &self,
        py: Python<'py>,
        t0: f64,
        t_end: f64,
        options: &Bound<'py, PyDict>,
        progress: Option<Py<PyAny>>,
        sink: Option<Py<PyAny>>,
        from_equilibrium: bool,
        initial_state: Option<Vec<f64>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let options = conv::simulation_options(options)?;
        let model = Arc::clone(&self.model);
        let raised = Arc::new(Mutex::new(None));
        let watched = Arc::new({
            let raised = Arc::clone(&raised);
            Progress::watched(WATCH_INTERVAL, move |t| Python::attach(|py| poll(py, progress.as_ref(), t, &raised)))
        });
        let channels = self.model.channel_infos().len();
        let sink = sink.map(|callable| {
            let progress = Arc::clone(&watched);
            Box::new(PythonSink { callable, channels, raised: Arc::clone(&raised), handed: 0, progress }) as Box<dyn SampleSink>
        });
        let run = py.detach(|| {
            guarded(|| {
                let mut ws = Workspace::new(&model);
                // (the start's Newton loops answer Ctrl-C too)
                let mut state = watched.scope(|| {
                    if let Some(y) = initial_state {
                        if y.len() != model.layout.len() {
                            let message = format!("an initial state of {} values, the model has {}", y.len(), model.layout.len());
                            return Err(jointplay_core::SimulationError::InvalidInput { time: t0, message });
                        }
                        Ok(dynamics::State::new(&model, t0, y))
                    } else if from_equilibrium {
                        dynamics::equilibrium(&model, t0, &dynamics::EquilibriumOptions::default(), &mut ws).map(|found| found.state)
                    } else {
                        dynamics::assemble(&model, t0, &mut ws)
                    }
                })?;
                // (an equilibrium start moves the bodies on purpose: nothing to note)
                let notes = if from_equilibrium { Vec::new() } else { dynamics::assembly_notes(&model, t0, state.coordinates(), &mut ws) };
                Ok((dynamics::simulate_with_sink(&model, &mut state, t_end, &options, Some(&*watched), sink), notes))
            })
        })?;
        if let Some(error) = raised.lock().map_err(|_| PyRuntimeError::new_err("callback state poisoned"))?.take() {
            return Err(error);
        }
        let out = PyDict::new(py);
        match run {
            Ok((outcome, notes)) => {
                conv::outcome(py, &out, outcome)?;
                out.set_item("assembly_notes", conv::assembly_notes(py, &notes)?)?;
            }
            Err(e) => {
                out.set_item("time", PyArray1::<f64>::zeros(py, 0, false))?;
                out.set_item("values", PyArray2::<f64>::zeros(py, [0, self.model.channel_infos().len()], false))?;
                conv::channel_infos(py, &out, &self.model.channel_infos())?;
                out.set_item("error", conv::simulation_error(py, &e)?)?;
                out.set_item("statistics", PyDict::new(py))?;
                out.set_item("diagnostics", PyDict::new(py))?;
                out.set_item("stage", "assembly")?;
            }
        }
        Ok(out)
    }
}

/// The jointplay core.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<CoreModel>()?;
    m.add_function(wrap_pyfunction!(compile_model, m)?)?;
    m.add_function(wrap_pyfunction!(spec_tables, m)?)?;
    m.add_function(wrap_pyfunction!(bearing::reynolds_solve, m)?)?;
    m.add_function(wrap_pyfunction!(bearing::steady_bearing, m)?)?;
    bearing::add_constants(m)?;
    m.add("MAX_STRUCTURE_NODES", jointplay_core::body::MAX_STRUCTURE_NODES)?;
    m.add("PROJECTION_SHARE", dynamics::PROJECTION_SHARE)?;
    m.add("PROJECTION_FLOOR", dynamics::PROJECTION_FLOOR)?;
    m.add("PROJECTION_CEILING", dynamics::PROJECTION_CEILING)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
