//! # jointplay-core
//!
//! The numerical core of jointplay: planar and spatial mechanisms with
//! ideal joints, revolute clearance joints (dry or lubricated), flexible
//! links, drivers and force elements, integrated by adaptive Runge-Kutta,
//! Adams, NDF or generalized-alpha methods with contact events.
//!
//! The folders read as a table of contents of the physics:
//!
//! - [`kinematics`]: the vocabulary bodies and elements speak (frames, markers, quaternions, Euler angles, wrenches);
//! - [`body`]: kinds of bodies behind one trait (planar rigid, beam, modal, spatial rigid);
//! - [`contact`]: normal contact force laws and contact stiffness laws;
//! - [`friction`]: tangential friction laws;
//! - [`motion`]: prescribed functions of time for drivers and loads;
//! - [`lubrication`]: journal-bearing film models and the Reynolds solver;
//! - [`joint`]: ideal joints from constraint primitives (planar and spatial), the clearance revolute joint as a force element;
//! - [`force`]: springs, dampers, bushings, applied loads, hydraulic cylinders;
//! - [`element`]: the one contract of every joint, driver and force element, and the list of their kinds;
//! - [`dynamics`]: the pipeline, one folder per stage: the compiled model and its state,
//!   the compiler, the formulations (equations of motion, projection), the starts
//!   (assembly, equilibrium), the outputs and the simulation driver;
//! - [`integrate`]: time integrators with dense output and event location;
//! - [`linalg`]: the small dense factorisations the hot loop uses without allocating;
//! - [`spec`]: the plain-data model description that the front ends produce.
//!
//! Data flows one way: a [`spec::ModelSpec`] is compiled into an immutable
//! [`dynamics::Model`]; [`dynamics::simulate`] advances a
//! [`dynamics::State`] with a reusable [`dynamics::Workspace`] and returns a
//! [`dynamics::Trajectory`] of named channels in SI units.
#![warn(missing_docs)]
// units are written in brackets, `[m]`, `[N]`: they are not links
#![allow(rustdoc::broken_intra_doc_links)]

pub mod beam;
pub mod body;
pub mod contact;
mod dispatch;
pub mod dynamics;
pub mod element;
pub mod error;
pub mod force;
pub mod friction;
pub mod hydraulic;
pub mod integrate;
pub mod interrupt;
pub mod joint;
pub mod kinematics;
pub mod linalg;
pub mod lubrication;
pub mod modal;
pub mod motion;
pub mod spec;

pub use error::{ModelError, ModelErrors, SimulationError};
