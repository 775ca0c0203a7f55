//! The allowed range of one key of the model description. The ranges
//! themselves are defined once, in `python/jointplay/parameters.py`, and
//! generated into [`super::ranges`]; the core checks values against them.

use crate::error::ModelErrors;

/// Bounds of a number (`gt`: greater than, `ge`: at least, `lt`: smaller
/// than, `le`: at most) and how a message says them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Range {
    /// The key the range belongs to (`"restitution"`).
    pub key: &'static str,
    /// Exclusive lower bound.
    pub gt: Option<f64>,
    /// Inclusive lower bound.
    pub ge: Option<f64>,
    /// Exclusive upper bound.
    pub lt: Option<f64>,
    /// Inclusive upper bound.
    pub le: Option<f64>,
    /// The range as a message says it after "must": `be > 0`, `lie in (0, 1]`.
    pub rule: &'static str,
    /// The SI unit of the key's values (`"m/s"`), empty for plain numbers.
    pub unit: &'static str,
}

impl Range {
    /// A range without bounds yet (any finite number).
    pub const fn new(key: &'static str, rule: &'static str, unit: &'static str) -> Self {
        Self { key, gt: None, ge: None, lt: None, le: None, rule, unit }
    }

    /// The same range, greater than `bound`.
    pub const fn gt(self, bound: f64) -> Self {
        Self { gt: Some(bound), ..self }
    }

    /// The same range, at least `bound`.
    pub const fn ge(self, bound: f64) -> Self {
        Self { ge: Some(bound), ..self }
    }

    /// The same range, smaller than `bound`.
    pub const fn lt(self, bound: f64) -> Self {
        Self { lt: Some(bound), ..self }
    }

    /// The same range, at most `bound`.
    pub const fn le(self, bound: f64) -> Self {
        Self { le: Some(bound), ..self }
    }

    /// Whether `value` is finite and within every bound.
    pub fn contains(&self, value: f64) -> bool {
        value.is_finite()
            && self.gt.is_none_or(|b| value > b)
            && self.ge.is_none_or(|b| value >= b)
            && self.lt.is_none_or(|b| value < b)
            && self.le.is_none_or(|b| value <= b)
    }

    /// `value` when it lies in the range, otherwise the message for the
    /// key's location: `must be > 0, got -0.001 m`.
    pub fn check(&self, value: f64) -> Result<f64, String> {
        if self.contains(value) {
            Ok(value)
        } else {
            let unit = if self.unit.is_empty() { String::new() } else { format!(" {}", self.unit) };
            Err(format!("must {}, got {value}{unit}", self.rule))
        }
    }
}

impl Range {
    /// Whether `value` lies in the range; a problem at `{loc}.{key}` when not.
    pub fn check_at(&self, value: f64, loc: &str, errors: &mut ModelErrors) -> bool {
        self.check(value).map_err(|message| errors.push(format!("{loc}.{}", self.key), message)).is_ok()
    }

    /// Whether every `(range, value)` lies in its range; a problem at each key that does not.
    pub fn check_all(checks: &[(Range, f64)], loc: &str, errors: &mut ModelErrors) -> bool {
        checks.iter().fold(true, |ok, (range, value)| range.check_at(*value, loc, errors) && ok)
    }

    /// As [`Self::check_all`] for keys that may be absent (`None`: nothing to check).
    pub fn check_given(checks: &[(Range, Option<f64>)], loc: &str, errors: &mut ModelErrors) -> bool {
        checks.iter().fold(true, |ok, (range, value)| value.is_none_or(|v| range.check_at(v, loc, errors)) && ok)
    }
}

#[cfg(test)]
mod tests {
    use super::Range;

    #[test]
    fn a_half_open_interval_keeps_its_closed_end_and_refuses_its_open_end_and_non_finite_values() {
        let unit_interval = Range::new("restitution", "lie in (0, 1]", "").gt(0.0).le(1.0);
        assert!(unit_interval.contains(1.0) && unit_interval.contains(1e-300));
        assert!(!unit_interval.contains(0.0) && !unit_interval.contains(1.0 + f64::EPSILON));
        assert!(!unit_interval.contains(f64::NAN) && !unit_interval.contains(f64::INFINITY));
        assert_eq!(unit_interval.check(0.0), Err("must lie in (0, 1], got 0".to_string()));
    }

    #[test]
    fn a_message_gives_the_value_in_the_si_unit() {
        let length = Range::new("free_length", "be >= 0", "m").ge(0.0);
        assert_eq!(length.check(0.0), Ok(0.0));
        assert_eq!(length.check(-0.001), Err("must be >= 0, got -0.001 m".to_string()));
    }
}
