//! Flexible links and the sensors on them, as the front ends describe them.

use serde::{Deserialize, Serialize};

/// A geometrically exact planar beam: a flexible link, straight and
/// unstressed at the start.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeamSpec {
    /// Name, unique in the model (bodies and beams share names).
    pub name: String,
    /// Approximate initial position of the first end [m].
    pub start: [f64; 2],
    /// Approximate initial position of the second end [m].
    pub end: [f64; 2],
    /// Cross-section.
    pub section: BeamSectionSpec,
    /// Division into elements.
    pub mesh: BeamMeshSpec,
    /// Retardation time of the strain-rate (Kelvin-Voigt) damping [s]; 0: undamped.
    pub damping_time: f64,
    /// Initial velocity of the first end [m/s]; with `angular_velocity`, the
    /// rigid motion the beam starts in, held and checked against the joints.
    /// Neither given: the rigid motion the assembled mechanism gives the beam.
    #[serde(default)]
    pub velocity: Option<[f64; 2]>,
    /// Initial angular velocity of the beam as a rigid link [rad/s] (see `velocity`).
    #[serde(default)]
    pub angular_velocity: Option<f64>,
    /// Named points by arclength from the first end (`start` and `end` are named already).
    pub points: Vec<BeamPointSpec>,
}

/// A named point of a beam's axis.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeamPointSpec {
    /// Name, unique within the beam.
    pub name: String,
    /// Arclength from the first end along the unstressed beam [m].
    pub arclength: f64,
}

/// How a beam is divided into elements of equal length: by their number or
/// by their largest length (exactly one of the two).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeamMeshSpec {
    /// Element interpolation.
    pub order: ElementOrderSpec,
    /// Number of elements.
    #[serde(default)]
    pub elements: Option<usize>,
    /// Largest element length [m]; the count is the beam's length over it, rounded up.
    #[serde(default)]
    pub element_length: Option<f64>,
}

/// Element interpolation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ElementOrderSpec {
    /// Two nodes.
    Linear,
    /// Three nodes.
    Quadratic,
}

/// A beam's cross-section.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum BeamSectionSpec {
    /// The stiffnesses and inertias per length given directly.
    Resultants {
        /// `E A` [N].
        axial_stiffness: f64,
        /// `k G A` [N].
        shear_stiffness: f64,
        /// `E I` [N m^2].
        bending_stiffness: f64,
        /// `rho A` [kg/m].
        mass_per_length: f64,
        /// `rho I` [kg m].
        rotary_inertia_per_length: f64,
    },
    /// Area, second moment and shear factor of a material.
    Properties {
        /// Area [m^2].
        area: f64,
        /// Second moment about the bending axis [m^4].
        second_moment: f64,
        /// Shear factor `k` [-].
        shear_factor: f64,
        /// Material.
        material: BeamMaterialSpec,
    },
    /// Solid rectangle of a material.
    Rectangle {
        /// Out of the plane [m].
        width: f64,
        /// In the plane of bending [m].
        height: f64,
        /// Material.
        material: BeamMaterialSpec,
    },
    /// Solid circle of a material.
    Circle {
        /// Diameter [m].
        diameter: f64,
        /// Material.
        material: BeamMaterialSpec,
    },
    /// Tube of a material.
    Tube {
        /// Outer diameter [m].
        outer_diameter: f64,
        /// Inner diameter [m].
        inner_diameter: f64,
        /// Material.
        material: BeamMaterialSpec,
    },
}

/// An isotropic elastic material: Young's modulus, density and exactly one of
/// Poisson's ratio and the shear modulus.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BeamMaterialSpec {
    /// Young's modulus `E` [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio `nu` [-].
    #[serde(default)]
    pub poisson_ratio: Option<f64>,
    /// Shear modulus `G` [Pa].
    #[serde(default)]
    pub shear_modulus: Option<f64>,
    /// Density [kg/m^3].
    pub density: f64,
}

/// A sensor: channels that no element's law produces.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum SensorSpec {
    /// Stress resultants of a beam's section and the axial strain of one of its fibres.
    StrainGauge {
        /// Name (its channels are `<name>.<quantity>`).
        name: String,
        /// A point of a beam, `"beam.point"`.
        point: String,
        /// Distance of the fibre from the axis, towards the left of the beam's direction [m].
        fibre: f64,
    },
}
