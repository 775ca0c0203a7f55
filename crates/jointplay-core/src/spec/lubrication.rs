//! Plain-data description of a lubricated clearance joint.

use serde::{Deserialize, Serialize};

/// Lubricant and film model of a clearance joint.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LubricationSpec {
    /// Film model.
    pub model: FilmModelSpec,
    /// Dynamic viscosity [Pa s].
    pub viscosity: f64,
    /// Hand-over from the film force to dry contact.
    pub transition: TransitionSpec,
    /// Options of the Reynolds solver: given for every film model, read by the Reynolds models only.
    pub reynolds: ReynoldsSpec,
}

/// Film models.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FilmModelSpec {
    /// Squeeze film only, short-bearing form (paper 000 after Phelan).
    SqueezeFilmShort,
    /// Squeeze film only, long-bearing form.
    SqueezeFilmLong,
    /// Hamrock, infinitely short bearing.
    HamrockShort,
    /// Hamrock, infinitely long bearing.
    HamrockLong,
    /// Frêne et al., infinitely short bearing.
    FreneShort,
    /// Frêne et al., infinitely long bearing.
    FreneLong,
    /// Pinkus and Sternlicht, infinitely long bearing.
    PinkusSternlichtLong,
    /// Finite-length Reynolds equation solved at every evaluation.
    ReynoldsExact,
    /// Finite-length Reynolds equation through precomputed force tables.
    ReynoldsTable,
}

/// Transition from film to dry contact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
#[serde(tag = "law", rename_all = "snake_case", deny_unknown_fields)]
pub enum TransitionSpec {
    /// Film force until contact, contact force after.
    Switch,
    /// Flores et al.: squeeze film faded out between `lubricated_limit` and contact.
    Flores {
        /// Eccentricity ratio where the fading starts [-].
        lubricated_limit: f64,
    },
    /// Paper 001: squeeze and wedge film faded out from the safe film thickness to contact.
    WangImproved {
        /// Safe film thickness [m]; none: 0.00015 of the bearing diameter (paper 001's design rule).
        #[serde(default)]
        safe_film_thickness: Option<f64>,
    },
}

/// Cavitation condition of the Reynolds solver.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CavitationSpec {
    /// Negative pressures dropped (half-Sommerfeld).
    Gumbel,
    /// Reynolds / Swift-Stieber: p >= 0 as a complementarity problem.
    SwiftStieber,
    /// Mass-conserving Elrod-Adams (JFO).
    ElrodAdams,
}

/// Options of the Reynolds solver.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ReynoldsSpec {
    /// Cavitation condition.
    pub cavitation: CavitationSpec,
    /// Grid cells around the circumference (default: the solver's).
    #[serde(default)]
    pub n_circumferential: Option<usize>,
    /// Grid cells along the axis (default: the solver's).
    #[serde(default)]
    pub n_axial: Option<usize>,
    /// Gauge pressure at the bearing ends [Pa].
    pub ambient_pressure: f64,
    /// Supply pressure of a circumferential groove at mid-length [Pa]; no groove when absent.
    #[serde(default)]
    pub groove_supply_pressure: Option<f64>,
}
