//! Error types of the core: problems found while compiling a model
//! description ([`ModelErrors`]) and failures during a simulation
//! ([`SimulationError`]).

use std::fmt;

/// One problem in a model description, located by a path such as
/// `joints[2].bearing`.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelError {
    /// Where the problem is (`joints[2].clearance`, `bodies[0].mass`).
    pub location: String,
    /// What is wrong, naming the offending value.
    pub message: String,
}

impl fmt::Display for ModelError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.location, self.message)
    }
}

/// Every problem found in a model description, one entry per problem.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ModelErrors(pub Vec<ModelError>);

impl ModelErrors {
    /// Records one problem at `location`.
    pub fn push(&mut self, location: impl Into<String>, message: impl Into<String>) {
        self.0.push(ModelError { location: location.into(), message: message.into() });
    }

    /// True when no problem was recorded.
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// `Ok(value)` when no problem was recorded, otherwise the problems.
    pub fn into_result<T>(self, value: T) -> Result<T, ModelErrors> {
        if self.is_empty() { Ok(value) } else { Err(self) }
    }
}

impl fmt::Display for ModelErrors {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (k, e) in self.0.iter().enumerate() {
            if k > 0 {
                writeln!(f)?;
            }
            write!(f, "{e}")?;
        }
        Ok(())
    }
}

impl std::error::Error for ModelErrors {}

/// A parameter of a law checked to be finite and > 0 [`unit`]; the message names it and its value.
pub(crate) fn positive(name: &str, unit: &str, value: f64) -> Result<f64, String> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(format!("{name} must be finite and > 0 {unit}, got {value}"))
    }
}

/// A parameter of a law checked to be finite and >= 0 [`unit`]; the message names it and its value.
pub(crate) fn non_negative(name: &str, unit: &str, value: f64) -> Result<f64, String> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(format!("{name} must be finite and >= 0 {unit}, got {value}"))
    }
}

/// Why a simulation stopped early. Every variant names the time [s]; those
/// raised by an element name it too.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimulationError {
    /// The step size controller asked for a step below the smallest allowed.
    #[error("step size {step:.3e} s fell below the minimum at t = {time:.6e} s{}", element_hint(element))]
    StepSizeUnderflow {
        /// Time reached [s].
        time: f64,
        /// Step size that was refused [s].
        step: f64,
        /// Element most likely responsible (for example the clearance joint with the deepest penetration), if known.
        element: Option<String>,
    },
    /// More steps than allowed were taken.
    #[error("the run exceeded max_steps = {max_steps} attempted steps at t = {time:.6e} s; raise simulation.max_steps (or look for why the steps are so small)")]
    TooManySteps {
        /// Time reached [s].
        time: f64,
        /// The limit that was hit.
        max_steps: usize,
    },
    /// A quantity became NaN or infinite.
    #[error("non-finite value in {element} at t = {time:.6e} s")]
    NonFinite {
        /// Time [s].
        time: f64,
        /// Element whose output was not finite (or `state` when the state itself was).
        element: String,
    },
    /// The constraint Jacobian lost rank: a locked or singular configuration.
    #[error("singular constraint Jacobian at t = {time:.6e} s near {element}: {cause}")]
    SingularConfiguration {
        /// Time [s].
        time: f64,
        /// Constraint (joint or driver) where the rank was lost.
        element: String,
        /// Explanation.
        cause: String,
    },
    /// Newton iteration on the constraints did not converge.
    #[error("constraints could not be satisfied at t = {time:.6e} s (residual {residual:.3e} in {element})")]
    ConstraintViolation {
        /// Time [s].
        time: f64,
        /// Constraint with the largest residual.
        element: String,
        /// Largest residual after the iteration [m or rad].
        residual: f64,
    },
    /// The mechanism has no static equilibrium near its assembled configuration.
    #[error("no static equilibrium at t = {time:.6e} s: {element} has {cause}")]
    NoEquilibrium {
        /// Time [s].
        time: f64,
        /// The body whose load is not carried.
        element: String,
        /// What is unbalanced.
        cause: String,
    },
    /// Initial velocities given for a flexible body contradict its joints.
    #[error("the initial velocities given for {element} contradict its joints and drivers at t = {time:.6e} s: {cause}")]
    ContradictoryVelocities {
        /// Time [s].
        time: f64,
        /// The body (or bodies) whose given velocities the joints contradict.
        element: String,
        /// What the joints need instead.
        cause: String,
    },
    /// A contact penetrated further than the sanity bound allows.
    #[error("penetration {penetration:.3e} m in {element} at t = {time:.6e} s exceeds the bound {bound:.3e} m; the contact is too soft or the step too large")]
    ExcessivePenetration {
        /// Time [s].
        time: f64,
        /// Clearance joint.
        element: String,
        /// Penetration depth [m].
        penetration: f64,
        /// The bound [m].
        bound: f64,
    },
    /// The assembled start is not one the description can mean: a flexible body
    /// strained far beyond any elastic link to close a loop, a journal started
    /// deep inside its bearing.
    #[error("{element} cannot start as assembled at t = {time:.6e} s: {cause}")]
    ImplausibleStart {
        /// Time [s].
        time: f64,
        /// Body or clearance joint.
        element: String,
        /// What assembly found, with the numbers.
        cause: String,
    },
    /// A film model failed (for example the Reynolds solver did not converge).
    #[error("film model of {element} failed at t = {time:.6e} s: {cause}")]
    FilmModel {
        /// Time [s].
        time: f64,
        /// Clearance joint.
        element: String,
        /// What went wrong.
        cause: String,
    },
    /// An element's state left the range where its law holds (a cylinder's
    /// stroke beyond its ends, a chamber pressure below absolute zero).
    #[error("{element} left the range of its law at t = {time:.6e} s: {cause}")]
    ElementOutOfRange {
        /// Time of the accepted step [s].
        time: f64,
        /// Element.
        element: String,
        /// What is out of range, with the values.
        cause: String,
    },
    /// The integration was asked for something it cannot do (bad options, t_end before t0, wrong state length).
    #[error("invalid integration input at t = {time:.6e} s: {message}")]
    InvalidInput {
        /// Start time [s].
        time: f64,
        /// What is wrong.
        message: String,
    },
    /// One more sample would make the output larger than its budget.
    #[error("output budget max_output_bytes = {budget} bytes reached at t = {time:.6e} s ({samples} samples x {channels} channels x 8 bytes); raise max_output_bytes, set a coarser output_step or a shorter t_end")]
    OutputBudgetExceeded {
        /// Time of the sample that did not fit [s].
        time: f64,
        /// Samples recorded (all within the budget).
        samples: usize,
        /// Channels per sample.
        channels: usize,
        /// The budget [bytes].
        budget: u64,
    },
    /// The sink receiving the samples (a results file) failed.
    #[error("writing the results failed at t = {time:.6e} s: {message}")]
    OutputSink {
        /// Time of the last sample handed over [s].
        time: f64,
        /// What the sink reported.
        message: String,
    },
    /// The run was interrupted from outside (for example Ctrl-C).
    #[error("interrupted at t = {time:.6e} s")]
    Interrupted {
        /// Time reached [s].
        time: f64,
    },
}

fn element_hint(element: &Option<String>) -> String {
    match element {
        Some(name) => format!(" (likely cause: {name})"),
        None => String::new(),
    }
}

impl SimulationError {
    /// Time at which the simulation stopped [s].
    pub fn time(&self) -> f64 {
        match self {
            Self::StepSizeUnderflow { time, .. }
            | Self::TooManySteps { time, .. }
            | Self::NonFinite { time, .. }
            | Self::SingularConfiguration { time, .. }
            | Self::ConstraintViolation { time, .. }
            | Self::ContradictoryVelocities { time, .. }
            | Self::NoEquilibrium { time, .. }
            | Self::ExcessivePenetration { time, .. }
            | Self::ImplausibleStart { time, .. }
            | Self::InvalidInput { time, .. }
            | Self::FilmModel { time, .. }
            | Self::ElementOutOfRange { time, .. }
            | Self::OutputBudgetExceeded { time, .. }
            | Self::OutputSink { time, .. }
            | Self::Interrupted { time } => *time,
        }
    }

    /// Element named by the error, if any.
    pub fn element(&self) -> Option<&str> {
        match self {
            Self::StepSizeUnderflow { element, .. } => element.as_deref(),
            Self::NonFinite { element, .. }
            | Self::SingularConfiguration { element, .. }
            | Self::ConstraintViolation { element, .. }
            | Self::ContradictoryVelocities { element, .. }
            | Self::NoEquilibrium { element, .. }
            | Self::ExcessivePenetration { element, .. }
            | Self::ImplausibleStart { element, .. }
            | Self::FilmModel { element, .. }
            | Self::ElementOutOfRange { element, .. } => Some(element),
            Self::TooManySteps { .. }
            | Self::InvalidInput { .. }
            | Self::OutputBudgetExceeded { .. }
            | Self::OutputSink { .. }
            | Self::Interrupted { .. } => None,
        }
    }
}
