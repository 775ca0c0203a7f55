//! Plain-data choices of laws and time functions.

use serde::{Deserialize, Serialize};

/// Elastic material.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// Young's modulus [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio [-].
    pub poisson_ratio: f64,
}

/// Normal contact force law.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum ContactSpec {
    /// Pure elastic Hertz.
    Hertz,
    /// Hunt-Crossley.
    HuntCrossley {
        /// Coefficient of restitution [-].
        restitution: f64,
    },
    /// Lankarani-Nikravesh.
    LankaraniNikravesh {
        /// Coefficient of restitution [-].
        restitution: f64,
    },
    /// Flores et al. 2011.
    Flores {
        /// Coefficient of restitution [-].
        restitution: f64,
    },
    /// Gonthier et al. 2004.
    Gonthier {
        /// Coefficient of restitution [-].
        restitution: f64,
    },
    /// Hu and Guo 2015.
    HuGuo {
        /// Coefficient of restitution [-].
        restitution: f64,
    },
}

/// Contact stiffness law.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum StiffnessSpec {
    /// `K delta^n`, `K = (4/3) E* sqrt(R*)`.
    HertzCylinder,
    /// Hertz-type law with a chosen exponent.
    HertzCylinderExponent {
        /// Exponent n [-].
        exponent: f64,
    },
    /// Johnson / ESDU line contact (needs the bearing length).
    JohnsonLine,
    /// Rogers-Andrews logarithmic law (needs the bearing length).
    RogersAndrews,
    /// Pereira-Ramalho-Ambrósio fitted power law of internal cylinder contact (needs the bearing length).
    PereiraRamalhoAmbrosio,
}

/// Friction law.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum FrictionSpec {
    /// Frictionless.
    None,
    /// Coulomb regularised by tanh.
    Coulomb {
        /// Friction coefficient [-].
        coefficient: f64,
        /// Regularisation velocity [m/s].
        velocity_tolerance: f64,
    },
    /// Modified Coulomb law of Ambrosio.
    Ambrosio {
        /// Friction coefficient [-].
        coefficient: f64,
        /// Velocity below which no friction acts [m/s].
        v0: f64,
        /// Velocity above which full friction acts [m/s].
        v1: f64,
    },
    /// Threlfall's exponential law.
    Threlfall {
        /// Friction coefficient [-].
        coefficient: f64,
        /// Velocity scale [m/s].
        v0: f64,
    },
    /// Static and kinetic coefficients with velocity tolerances.
    Stiction {
        /// Static coefficient [-].
        static_coefficient: f64,
        /// Kinetic coefficient [-].
        kinetic_coefficient: f64,
        /// Velocity at which the static coefficient is reached [m/s].
        stiction_velocity: f64,
        /// Velocity from which the kinetic coefficient holds [m/s].
        transition_velocity: f64,
    },
}

/// A function of time.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum FunctionSpec {
    /// Constant value.
    Constant {
        /// Value.
        value: f64,
    },
    /// `initial + rate t` (constant speed).
    ConstantRate {
        /// Value at t = 0.
        initial: f64,
        /// Rate per second.
        rate: f64,
    },
    /// `sum c_k t^k`.
    Polynomial {
        /// Coefficients, constant first.
        coefficients: Vec<f64>,
    },
    /// Smooth cubic step from `value_start` at `t_start` to `value_end` at `t_end`.
    CubicStep {
        /// Start time [s].
        t_start: f64,
        /// End time [s].
        t_end: f64,
        /// Value before the step.
        value_start: f64,
        /// Value after the step.
        value_end: f64,
    },
    /// `offset + amplitude sin(2 pi frequency t + phase)`.
    Sine {
        /// Mean value.
        offset: f64,
        /// Amplitude.
        amplitude: f64,
        /// Frequency [Hz].
        frequency: f64,
        /// Phase [rad].
        phase: f64,
    },
    /// Natural cubic spline through a table.
    Table {
        /// Times [s], strictly increasing.
        times: Vec<f64>,
        /// Values.
        values: Vec<f64>,
    },
    /// Rate rising smoothly from zero at t = 0 to `final_rate` at `ramp_time`, constant after (a spin-up).
    SpeedRamp {
        /// Duration of the ramp [s].
        ramp_time: f64,
        /// Rate after the ramp (value per second).
        final_rate: f64,
    },
}
