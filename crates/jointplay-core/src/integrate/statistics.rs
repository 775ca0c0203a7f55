//! Counters of an integration run.

/// What an integration run did, counted exactly (see the theory pages for
/// how `rhs_evaluations` follows from the other counts for each method).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Statistics {
    /// Steps whose error estimate passed.
    pub accepted_steps: usize,
    /// Steps whose error estimate failed (or was not finite).
    pub rejected_steps: usize,
    /// Calls of `OdeSystem::rhs`, including the starting-step heuristic.
    pub rhs_evaluations: usize,
    /// Events handled (`on_event` calls).
    pub events: usize,
    /// Smallest accepted step [s] (0 when no step was taken).
    pub smallest_step: f64,
    /// Largest accepted step [s] (0 when no step was taken).
    pub largest_step: f64,
    /// Restarts after an event or after `accept()` returned true.
    pub restarts: usize,
    /// Jacobians formed (implicit method only), by forward differences or by the system.
    pub jacobian_evaluations: usize,
    /// Of `rhs_evaluations`, those spent on Jacobians: n + 1 for each formed by
    /// forward differences, 1 (the evaluation at the Jacobian's state) for each
    /// the system formed itself.
    pub jacobian_rhs_evaluations: usize,
    /// Evaluations of the local forces (the elements' forces and state rates,
    /// without the mass and constraint solves of a right-hand side) spent on the
    /// Jacobians the system formed itself: one at the Jacobian's state and one
    /// per colour of coordinates perturbed together, each evaluating only the
    /// elements that read a perturbed coordinate (`docs/theory/integrator-jacobian.md`).
    pub jacobian_force_evaluations: usize,
    /// LU factorisations of the Newton iteration matrix (implicit method only).
    pub factorizations: usize,
    /// Of those, the factorisations of the sparse augmented Newton matrix (a system that
    /// describes its Jacobian's structure; `docs/theory/integrator-jacobian.md`).
    pub sparse_factorizations: usize,
}

impl Statistics {
    /// Counts one accepted step of size `h` [s].
    pub(crate) fn count_accepted(&mut self, h: f64) {
        self.accepted_steps += 1;
        if self.accepted_steps == 1 {
            self.smallest_step = h;
            self.largest_step = h;
        } else {
            self.smallest_step = self.smallest_step.min(h);
            self.largest_step = self.largest_step.max(h);
        }
    }
}
