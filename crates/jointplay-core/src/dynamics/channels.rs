//! Output channels `"<element>.<quantity>"` in SI units and their values
//! at a sample (the [`super::Trajectory`] records them).

use super::frame::cross;
use super::model::ElementKind;
use crate::body::BodyKind;
use super::{Model, Workspace};

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
    /// Ideal element (joint or driver): the index of the output among its kind's channels.
    Ideal(usize, u8),
    /// Force element (clearance joints included): the index of the output among its channels.
    Force(usize, u8),
    /// Strain gauge: the index of the output among [`super::model::StrainGauge::CHANNELS`].
    Gauge(usize, u8),
    /// 0 kinetic, 1 potential, 2 total mechanical energy.
    Energy(u8),
}

/// A channel and its source.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Channel {
    pub info: ChannelInfo,
    pub source: Source,
}

/// Appends the values of all channels at one sample (in the order of
/// `model.channels`) to `out`, after filling the workspace's
/// `constraint_forces` once for all reaction channels.
pub(crate) fn append_sample(model: &Model, y: &[f64], ws: &mut Workspace, out: &mut Vec<f64>) {
    update_constraint_forces(model, ws);
    let ws = &*ws;
    let energy = kinetic_and_potential_energy(model, y, ws);
    out.extend(model.channels.iter().map(|channel| value(model, channel.source, y, ws, energy)));
}

/// The value of one channel; `energy` is `[kinetic, potential]` [J] of the sample.
pub(crate) fn value(model: &Model, source: Source, y: &[f64], ws: &Workspace, energy: [f64; 2]) -> f64 {
    match source {
        Source::Coordinate(k) => y[k],
        Source::Velocity(k) => y[model.layout.nq + k],
        Source::Acceleration(k) => ws.accelerations[k],
        Source::Ideal(e, which) => match model.elements[e].kind {
            ElementKind::AngleDriver | ElementKind::DisplacementDriver => driver_effort(model, e, ws),
            _ => reaction_value(model, e, which, ws),
        },
        Source::Force(f, which) => model.forces[f].output(which as usize, &ws.frames, &ws.element_work[f]),
        Source::Gauge(k, which) => gauge_value(model, k, which, y),
        Source::Energy(0) => energy[0],
        Source::Energy(1) => energy[1],
        Source::Energy(_) => energy[0] + energy[1],
    }
}

/// Output `which` of strain gauge `k` at the state `y`.
fn gauge_value(model: &Model, k: usize, which: u8, y: &[f64]) -> f64 {
    let gauge = &model.gauges[k];
    let address = &model.layout.bodies[gauge.body.0 - 1];
    let (q, v, _) = model.layout.split(y);
    let (strains, resultants) = match &model.bodies[gauge.body.0 - 1].kind {
        BodyKind::Beam(beam) => beam.section_state(&gauge.site, &q[address.q_range()], &v[address.v_range()]),
        BodyKind::Modal(modal) => modal.section_state(&gauge.site, &gauge.strain_modes, &q[address.q_range()]).expect("a gauge on a modal body is compiled only when it was reduced from a beam"),
        _ => unreachable!("a strain gauge sits on a beam or a modal body"),
    };
    match which {
        0..=2 => resultants[which as usize],
        3 => strains.axial - gauge.fibre * strains.curvature,
        4 => strains.axial,
        _ => strains.curvature,
    }
}

/// Fills `ws.constraint_forces` for every element acting during the
/// simulation (assembly locks keep zero).
pub(crate) fn update_constraint_forces(model: &Model, ws: &mut Workspace) {
    if ws.joint.active {
        if let Ok(tree) = &model.joint_tree {
            tree.reactions(model, ws);
        }
        return;
    }
    for (e, element) in model.elements.iter().enumerate() {
        if element.constraints.end <= model.n_dynamic_constraints {
            ws.constraint_forces[e] = constraint_force_on_second(model, e, ws);
        }
    }
}

/// Generalised constraint force `(fx, fy, moment about the centre of mass)`
/// that element `e` exerts on its second body (on its first, negated, when the
/// second is the ground): the loads of its rows' multipliers, `-Phi_q^T lambda`,
/// as each primitive states them at its markers.
fn constraint_force_on_second(model: &Model, e: usize, ws: &Workspace) -> [f64; 3] {
    let element = &model.elements[e];
    let (slot, sign) = if element.second.is_ground() { (0, -1.0) } else { (1, 1.0) };
    let centre = ws.frames[element.frames[slot]].position;
    let mut g = [0.0; 3];
    for k in element.constraints.clone() {
        let rows = model.row_offsets[k]..model.row_offsets[k + 1];
        let load = model.constraints[k].kind.loads(&ws.frames, &ws.multipliers[rows])[slot];
        g[0] += sign * load.force.x;
        g[1] += sign * load.force.y;
        g[2] += sign * (load.moment + cross(load.point - centre, load.force));
    }
    g
}

fn reaction_value(model: &Model, e: usize, which: u8, ws: &Workspace) -> f64 {
    let [fx, fy, moment] = ws.constraint_forces[e];
    match which {
        0 => fx,
        1 => fy,
        2 => (fx * fx + fy * fy).sqrt(),
        _ => {
            // moment about the element's point on the second body
            let element = &model.elements[e];
            let frame = &ws.frames[element.frames[1]];
            moment - cross(frame.rotate(element.second_point), nalgebra::Vector2::new(fx, fy))
        }
    }
}

fn driver_effort(model: &Model, e: usize, ws: &Workspace) -> f64 {
    let element = &model.elements[e];
    let [fx, fy, moment] = ws.constraint_forces[e];
    match element.kind {
        ElementKind::DisplacementDriver => ws.frames[element.frames[0]].rotate(element.axis).dot(&nalgebra::Vector2::new(fx, fy)),
        _ => moment,
    }
}

/// Kinetic and potential energy [J] of the state y (gravity, strain of flexible bodies, force elements and contacts).
fn kinetic_and_potential_energy(model: &Model, y: &[f64], ws: &Workspace) -> [f64; 2] {
    let (q, v, _) = model.layout.split(y);
    let bodies = model.bodies.iter().zip(&model.layout.bodies);
    let kinetic: f64 = bodies.clone().map(|(b, a)| b.kind.kinetic_energy(&q[a.q_range()], &v[a.v_range()])).sum();
    let own: f64 = bodies.map(|(b, a)| b.kind.potential_energy(model.gravity, &q[a.q_range()])).sum();
    let elements: f64 = model.forces.iter().zip(&ws.element_work).map(|(element, work)| element.potential_energy(work)).sum();
    let potential = own + elements;
    [kinetic, potential]
}
