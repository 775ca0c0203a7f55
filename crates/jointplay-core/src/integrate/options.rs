//! Integrator options: method, tolerances, step limits and output spacing,
//! with defaults that carry their reasons and a validation of every field.

/// Time-integration method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Explicit Runge-Kutta 5(4) of Dormand & Prince (1980) with FSAL,
    /// PI step control and Shampine's 4th-order dense output.
    DormandPrince45,
    /// Variable-step Adams-Bashforth-Moulton PECE of order up to 4 with
    /// Milne's error estimate, started with an order ramp from order 1.
    AdamsPredictorCorrector,
    /// Variable-order (1 to 5) numerical differentiation formulas of
    /// Shampine & Reichelt (1997), implicit, with simplified Newton
    /// iterations on a finite-difference or the system's own Jacobian: for stiff problems.
    NumericalDifferentiation,
    /// Generalized-alpha for first-order systems (Jansen, Whiting & Hulbert
    /// 2000), implicit, second order, with a fixed nominal step
    /// ([`IntegratorOptions::step`]) and the numerical damping of unresolved
    /// vibrations set by [`IntegratorOptions::spectral_radius`]: for flexible bodies.
    GeneralizedAlpha,
}

/// How the implicit method forms the Jacobian `df/dy` of its Newton iterations.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum JacobianMethod {
    /// The system's own Jacobian where it says that it pays
    /// ([`SystemJacobian::Preferred`](super::SystemJacobian::Preferred): a
    /// mechanism in absolute coordinates with a beam), forward differences otherwise.
    Auto,
    /// Forward differences of the whole right-hand side: n + 1 evaluations.
    FiniteDifference,
    /// The system's own Jacobian wherever it has one (forward differences where not).
    Structured,
}

/// Options of [`integrate`](super::integrate); check them with [`IntegratorOptions::validate`].
#[derive(Clone, Debug, PartialEq)]
pub struct IntegratorOptions {
    /// Integration method.
    pub method: Method,
    /// Relative tolerance of the local error [-].
    pub rtol: f64,
    /// Absolute tolerance of the local error [state units].
    pub atol: f64,
    /// Largest step [s]; `f64::INFINITY` for none.
    pub max_step: f64,
    /// First step [s]; `None` picks it with Hairer's starting-step heuristic.
    pub initial_step: Option<f64>,
    /// Smallest step the controller may ask for before the run stops with
    /// `StepSizeUnderflow` [s].
    pub min_step: f64,
    /// Largest number of attempted (accepted + rejected) steps; the default
    /// 10 000 000 stops a run whose steps have collapsed within minutes
    /// instead of letting it run for hours.
    pub max_steps: usize,
    /// Spacing of output samples taken from the dense output [s]; `None`
    /// records every accepted step.
    pub output_step: Option<f64>,
    /// Highest order of the numerical differentiation formulas, 1 to 5
    /// (ignored by the other methods). Orders 1 and 2 are A-stable; the higher
    /// ones lose stability near the imaginary axis, where the undamped
    /// vibrations of a flexible body put their eigenvalues (Shampine and
    /// Reichelt, "The MATLAB ODE suite", SIAM J. Sci. Comput. 18 (1997) 1-22, §2.2).
    pub max_order: usize,
    /// How the implicit methods form their Jacobian (ignored by the explicit methods).
    pub jacobian: JacobianMethod,
    /// Nominal step of generalized-alpha [s], required by it (ignored by the
    /// error-controlled methods); halved where the Newton iterations fail.
    pub step: Option<f64>,
    /// Spectral radius at infinity rho_inf of generalized-alpha, 0 to 1: the
    /// factor by which a step multiplies a vibration it does not resolve
    /// (1: no numerical damping; 0: removed in one step). Ignored by the other methods.
    pub spectral_radius: f64,
}

/// Smallest relative tolerance accepted: 100 machine epsilons, below which
/// the error estimate is dominated by rounding.
pub const MIN_RTOL: f64 = 100.0 * f64::EPSILON;

impl Default for IntegratorOptions {
    /// Dormand-Prince, rtol 1e-6 (six digits, finer than plotted curves),
    /// atol 1e-9 (nanometre-scale for positions in metres), no step limit,
    /// automatic first step, min_step 1e-14 s (far below any contact time
    /// scale, above rounding of t), 10 million steps, a sample per step,
    /// the Jacobian chosen automatically (`docs/theory/integrator-jacobian.md`),
    /// no generalized-alpha step (that method requires one) and its spectral
    /// radius 0.9 (Exudyn's default; the damping of a vibration at 10 steps per
    /// period stays below 1 % a period, `docs/theory/integrator-generalized-alpha.md`).
    fn default() -> Self {
        Self {
            method: Method::DormandPrince45,
            rtol: 1e-6,
            atol: 1e-9,
            max_step: f64::INFINITY,
            initial_step: None,
            min_step: 1e-14,
            max_steps: 10_000_000,
            output_step: None,
            max_order: 5,
            jacobian: JacobianMethod::Auto,
            step: None,
            spectral_radius: 0.9,
        }
    }
}

impl IntegratorOptions {
    /// Checks every field; the error lists one `field: problem, got value` per problem, joined by `; `.
    pub fn validate(&self) -> Result<(), String> {
        let mut problems: Vec<String> = Vec::new();
        let mut check = |ok: bool, field: &str, rule: &str, got: String| {
            if !ok {
                problems.push(format!("{field}: must be {rule}, got {got}"));
            }
        };
        check(self.rtol.is_finite() && self.rtol >= MIN_RTOL, "rtol", ">= 2.2e-14 and finite", fmt(self.rtol));
        check(self.atol.is_finite() && self.atol >= 0.0, "atol", ">= 0 and finite", fmt(self.atol));
        check(self.max_step > 0.0, "max_step", "> 0 s", fmt(self.max_step));
        check(self.min_step.is_finite() && self.min_step >= 0.0, "min_step", ">= 0 s and finite", fmt(self.min_step));
        check(self.min_step < self.max_step, "min_step", "< max_step", fmt(self.min_step));
        check(self.max_steps >= 1, "max_steps", ">= 1", self.max_steps.to_string());
        if let Some(h) = self.initial_step {
            check(h.is_finite() && h > 0.0, "initial_step", "> 0 s and finite", fmt(h));
            check(h >= self.min_step, "initial_step", ">= min_step", fmt(h));
        }
        check((1..=5).contains(&self.max_order), "max_order", "1 to 5", self.max_order.to_string());
        check((0.0..=1.0).contains(&self.spectral_radius), "spectral_radius", "0 to 1", fmt(self.spectral_radius));
        match self.step {
            Some(h) => {
                check(h.is_finite() && h > 0.0, "step", "> 0 s and finite", fmt(h));
                check(h >= self.min_step, "step", ">= min_step", fmt(h));
            }
            None => check(self.method != Method::GeneralizedAlpha, "step", "given with generalized_alpha (its fixed nominal step)", "none".into()),
        }
        if let Some(dt) = self.output_step {
            check(dt.is_finite() && dt > 0.0, "output_step", "> 0 s and finite", fmt(dt));
        }
        if problems.is_empty() { Ok(()) } else { Err(problems.join("; ")) }
    }
}

fn fmt(x: f64) -> String {
    format!("{x:e}")
}
