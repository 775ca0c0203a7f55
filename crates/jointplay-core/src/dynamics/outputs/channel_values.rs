//! The values of the output channels at a sample (the
//! [`super::trajectory::Trajectory`] records them); what a channel is and
//! how a sample reads it is `model/channels.rs`.

use super::spatial_reactions::{spatial_driver_effort, spatial_reactions};

use crate::kinematics::planar::cross;
use crate::dynamics::model::channels::{is_driver, ChannelRead, Source};
use crate::dynamics::model::mechanism::Model;
use crate::element::ElementModel;
use crate::joint::IdealKind;
use crate::body::{BodyKind, BodyModel};
use crate::dynamics::formulations::workspace::Workspace;

/// Appends the values of all channels at one sample (in the order of
/// `model.channels`) to `out`, after filling the workspace's
/// `constraint_forces` once for all reaction channels.
pub(crate) fn append_sample(model: &Model, y: &[f64], ws: &mut Workspace, out: &mut Vec<f64>) {
    let start = out.len();
    out.resize(start + model.channels.len(), 0.0);
    read_channels(model, &model.channel_reads, y, ws, &mut out[start..]);
}

/// The values of the channels `reads` reads at the evaluation the workspace
/// holds at `y` into `out` (one per channel), after filling the workspace's
/// `constraint_forces` once for all reaction channels.
pub(crate) fn read_channels(model: &Model, reads: &[ChannelRead], y: &[f64], ws: &mut Workspace, out: &mut [f64]) {
    update_constraint_forces(model, ws);
    let ws = &*ws;
    let (q, v, _) = model.layout.split(y);
    let mut at = 0;
    for read in reads {
        let out = &mut out[at..at + read.len()];
        at += out.len();
        match read {
            ChannelRead::Coordinates(r) => out.copy_from_slice(&q[r.clone()]),
            ChannelRead::Velocities(r) => out.copy_from_slice(&v[r.clone()]),
            ChannelRead::Accelerations(r) => out.copy_from_slice(&ws.accelerations[r.clone()]),
            ChannelRead::ForceOutputs { element, outputs } => model.elements[*element].kind.outputs(outputs.clone(), &ws.frames, &ws.element_work[*element], out),
            ChannelRead::Reactions { element, outputs } if model.ideal(*element).spatial_markers.is_some() => {
                out.copy_from_slice(&spatial_reactions(model, *element, ws)[outputs.clone()]);
            }
            ChannelRead::Reactions { element, outputs } => out.copy_from_slice(&reactions(model, *element, ws)[outputs.clone()]),
            ChannelRead::Energies(r) => {
                let [kinetic, potential] = kinetic_and_potential_energy(model, y, ws);
                out.copy_from_slice(&[kinetic, potential, kinetic + potential][r.clone()]);
            }
            ChannelRead::One(source) => out[0] = value(model, *source, y, ws, [f64::NAN; 2]),
        }
    }
}

/// The value of one channel; `energy` is `[kinetic, potential]` [J] of the sample.
pub(crate) fn value(model: &Model, source: Source, y: &[f64], ws: &Workspace, energy: [f64; 2]) -> f64 {
    match source {
        Source::Coordinate(k) => y[k],
        Source::Velocity(k) => y[model.layout.nq + k],
        Source::Acceleration(k) => ws.accelerations[k],
        Source::Ideal(e, which) if model.ideal(e).spatial_markers.is_some() => match model.ideal(e).kind {
            IdealKind::SpatialAngleDriver => spatial_driver_effort(model, e, ws, true),
            IdealKind::SpatialDisplacementDriver => spatial_driver_effort(model, e, ws, false),
            _ => spatial_reactions(model, e, ws)[which as usize],
        },
        Source::Ideal(e, which) => if is_driver(model, e) { driver_effort(model, e, ws) } else { reactions(model, e, ws)[which as usize] },
        Source::Force(f, which) => model.elements[f].kind.output(which as usize, &ws.frames, &ws.element_work[f]),
        Source::Gauge(k, which) => gauge_value(model, k, which, y),
        Source::Derived(k, which) => {
            let (address, (q, v, _)) = (&model.layout.bodies[k], model.layout.split(y));
            model.bodies[k].kind.derived_value(&q[address.q_range()], &v[address.v_range()], which as usize)
        }
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
    for (e, element) in model.ideal_elements() {
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
    let element = model.ideal(e);
    let (slot, sign) = if element.second.is_ground() { (0, -1.0) } else { (1, 1.0) };
    let centre = ws.frames[element.frames[slot]].position;
    let mut g = [0.0; 3];
    for k in element.constraints.clone() {
        let rows = model.row_offsets[k]..model.row_offsets[k + 1];
        let load = model.constraints[k].kind.loads(&ws.frames(), &ws.multipliers[rows])[slot];
        g[0] += sign * load.force.x;
        g[1] += sign * load.force.y;
        g[2] += sign * (load.moment + cross(load.point - centre, load.force));
    }
    g
}

/// The reaction outputs `[fx, fy, f, moment]` of ideal joint `e` from `ws.constraint_forces`
/// (the moment about the element's point on its second body).
fn reactions(model: &Model, e: usize, ws: &Workspace) -> [f64; 4] {
    let [fx, fy, moment] = ws.constraint_forces[e];
    let element = model.ideal(e);
    let frame = &ws.frames[element.frames[1]];
    [fx, fy, (fx * fx + fy * fy).sqrt(), moment - cross(frame.rotate(element.second_point), nalgebra::Vector2::new(fx, fy))]
}

fn driver_effort(model: &Model, e: usize, ws: &Workspace) -> f64 {
    let element = model.ideal(e);
    let [fx, fy, moment] = ws.constraint_forces[e];
    match element.kind {
        IdealKind::DisplacementDriver => ws.frames[element.frames[0]].rotate(element.axis).dot(&nalgebra::Vector2::new(fx, fy)),
        _ => moment,
    }
}

/// Kinetic and potential energy [J] of the state y (gravity, strain of flexible bodies, force elements and contacts).
fn kinetic_and_potential_energy(model: &Model, y: &[f64], ws: &Workspace) -> [f64; 2] {
    let (q, v, _) = model.layout.split(y);
    let bodies = model.bodies.iter().zip(&model.layout.bodies);
    let kinetic: f64 = bodies.clone().map(|(b, a)| b.kind.kinetic_energy(&q[a.q_range()], &v[a.v_range()])).sum();
    let own: f64 = bodies.map(|(b, a)| b.kind.potential_energy(model.gravity, &q[a.q_range()])).sum();
    let elements: f64 = model.elements.iter().zip(&ws.element_work).map(|(element, work)| element.kind.potential_energy(work)).sum();
    let potential = own + elements;
    [kinetic, potential]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::formulations::absolute::equations::{accelerations, Stabilization};
    use crate::dynamics::assemble;

    #[test]
    fn a_sample_read_by_runs_equals_every_channel_read_alone() {
        // a slider-crank with a clearance joint (contact outputs), reactions of a driven
        // joint, a driver's effort and the energies; its pin in contact after a push
        let model = crate::dynamics::modal_tests::slider_crank(false, true);
        let mut ws = Workspace::new(&model);
        let mut state = assemble(&model, 0.0, &mut ws).unwrap();
        let nq = model.layout.nq;
        for v in &mut state.y[nq..nq + model.layout.nv] {
            *v += 0.3;
        }
        accelerations(&model, &state.memory, 0.0, &state.y, Stabilization::Projection, &mut ws).unwrap();
        let reads = &model.channel_reads;
        assert!(reads.len() < model.channels.len() / 2, "runs join channels: {} reads of {}", reads.len(), model.channels.len());
        assert!(reads.iter().any(|r| matches!(r, ChannelRead::ForceOutputs { outputs, .. } if outputs.len() > 5)));
        assert!(reads.iter().any(|r| matches!(r, ChannelRead::Reactions { outputs, .. } if outputs.len() > 2)));
        let mut sample = Vec::new();
        append_sample(&model, &state.y, &mut ws, &mut sample);
        let energy = kinetic_and_potential_energy(&model, &state.y, &ws);
        assert_eq!(sample.len(), model.channels.len());
        for (k, channel) in model.channels.iter().enumerate() {
            let alone = value(&model, channel.source, &state.y, &ws, energy);
            assert_eq!(sample[k].to_bits(), alone.to_bits(), "{}: {} vs {alone}", channel.info.name, sample[k]);
        }
        // a subset (the tracker's) reads the same values
        let subset: Vec<usize> = (0..model.channels.len()).filter(|c| c % 3 != 1).collect();
        let subset_reads = ChannelRead::plan(&model, subset.iter().map(|&c| model.channels[c].source));
        let mut values = vec![0.0; subset.len()];
        read_channels(&model, &subset_reads, &state.y, &mut ws, &mut values);
        for (v, &c) in values.iter().zip(&subset) {
            assert_eq!(v.to_bits(), sample[c].to_bits(), "{}", model.channels[c].info.name);
        }
    }
}
