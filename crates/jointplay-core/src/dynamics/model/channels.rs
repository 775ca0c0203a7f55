//! Output channels `"<element>.<quantity>"` in SI units: their names, units
//! and sources, and the plan by which a sample reads them (their values are
//! read by `outputs/channel_values.rs`).

use std::ops::Range;

use super::mechanism::Model;

/// Name, unit and meaning of one channel.
#[derive(Clone, Debug, PartialEq)]
pub struct ChannelInfo {
    /// `"<element>.<quantity>"`, e.g. `slider.ax`.
    pub name: String,
    /// SI unit (`m`, `m/s^2`, `N`, `1` for dimensionless).
    pub unit: &'static str,
    /// One-line description.
    pub description: String,
}

/// Where a channel's value comes from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Source {
    /// Coordinate `k` of `q` (position or angle).
    Coordinate(usize),
    /// Rate of coordinate `k`.
    Velocity(usize),
    /// Acceleration of coordinate `k`.
    Acceleration(usize),
    /// Ideal element (joint or driver; an index into `Model::elements`): the index of the output among its kind's channels.
    Ideal(usize, u8),
    /// Element acting through forces (clearance joints included; an index into `Model::elements`): the index of the output among its channels.
    Force(usize, u8),
    /// Strain gauge: the index of the output among [`super::mechanism::StrainGauge::CHANNELS`].
    Gauge(usize, u8),
    /// 0 kinetic, 1 potential, 2 total mechanical energy.
    Energy(u8),
    /// Body `k`'s derived channel (a spatial body's global angular velocity, Euler angles).
    Derived(usize, u8),
}

/// A channel and its source.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Channel {
    pub info: ChannelInfo,
    pub source: Source,
}

/// How a sample reads a run of channels that one computation serves: a body's
/// consecutive coordinates, rates or accelerations as one copy, an element's
/// consecutive outputs from one evaluation of them (a recorded sample costs
/// a dispatch per run instead of one per channel).
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum ChannelRead {
    /// Coordinates `q[range]`.
    Coordinates(Range<usize>),
    /// Rates `v[range]`.
    Velocities(Range<usize>),
    /// Accelerations `v_dot[range]`.
    Accelerations(Range<usize>),
    /// Outputs `outputs` of force element `element`.
    ForceOutputs { element: usize, outputs: Range<usize> },
    /// Reaction outputs `outputs` (`fx, fy, f, moment`) of the ideal joint `element`.
    Reactions { element: usize, outputs: Range<usize> },
    /// Energies `[kinetic, potential, total][range]`.
    Energies(Range<usize>),
    /// One channel of any other source.
    One(Source),
}

impl ChannelRead {
    /// The reads of channels with these sources, in their order.
    pub(crate) fn plan(model: &Model, sources: impl IntoIterator<Item = Source>) -> Vec<ChannelRead> {
        let mut reads: Vec<ChannelRead> = Vec::new();
        for source in sources {
            let joined = match (reads.last_mut(), source) {
                (Some(Self::Coordinates(r)), Source::Coordinate(k))
                | (Some(Self::Velocities(r)), Source::Velocity(k))
                | (Some(Self::Accelerations(r)), Source::Acceleration(k)) => Self::extend(r, k),
                (Some(Self::ForceOutputs { element, outputs }), Source::Force(f, which)) if *element == f => Self::extend(outputs, which as usize),
                (Some(Self::Reactions { element, outputs }), Source::Ideal(e, which)) if *element == e => Self::extend(outputs, which as usize),
                (Some(Self::Energies(r)), Source::Energy(which)) => Self::extend(r, which as usize),
                _ => false,
            };
            if joined {
                continue;
            }
            reads.push(match source {
                Source::Coordinate(k) => Self::Coordinates(k..k + 1),
                Source::Velocity(k) => Self::Velocities(k..k + 1),
                Source::Acceleration(k) => Self::Accelerations(k..k + 1),
                Source::Force(f, which) => Self::ForceOutputs { element: f, outputs: which as usize..which as usize + 1 },
                Source::Ideal(e, which) if !is_driver(model, e) => Self::Reactions { element: e, outputs: which as usize..which as usize + 1 },
                Source::Energy(which) => Self::Energies(which as usize..which as usize + 1),
                source => Self::One(source),
            });
        }
        reads
    }

    /// Extends `range` by `k` when `k` is its next index.
    fn extend(range: &mut Range<usize>, k: usize) -> bool {
        let next = range.end == k;
        if next {
            range.end += 1;
        }
        next
    }

    /// Number of channels it reads.
    pub(crate) fn len(&self) -> usize {
        match self {
            Self::Coordinates(r) | Self::Velocities(r) | Self::Accelerations(r) | Self::Energies(r) => r.len(),
            Self::ForceOutputs { outputs, .. } | Self::Reactions { outputs, .. } => outputs.len(),
            Self::One(_) => 1,
        }
    }
}

/// Whether ideal element `e` is a driver (one output, its effort).
pub(crate) fn is_driver(model: &Model, e: usize) -> bool {
    model.ideal(e).kind.is_driver()
}
