//! The range of every key of the model description that has one, generated from
//! `python/jointplay/parameters.py` by `python -m jointplay.boundary`: edit the ranges there,
//! then regenerate (`tests/test_parameter_boundary.py` fails while this file differs).

use super::range::Range;

/// `bodies.mass`: mass of the body [kg].
pub const BODIES_MASS: Range = Range::new("mass", "be > 0", "kg").gt(0.0);

/// `bodies.inertia`: moment of inertia about the centre of mass [kg m^2].
pub const BODIES_INERTIA: Range = Range::new("inertia", "be > 0", "kg m^2").gt(0.0);

/// `beams.element_length`: largest element length: the count is the length over it, rounded up [m].
pub const BEAMS_ELEMENT_LENGTH: Range = Range::new("element_length", "be > 0", "m").gt(0.0);

/// `beams.damping_time`: retardation time tau of strain-rate (Kelvin-Voigt) damping: each stress resultant gains
/// tau times its rate [s].
pub const BEAMS_DAMPING_TIME: Range = Range::new("damping_time", "be >= 0", "s").ge(0.0);

/// `modal_bodies.element_length`: largest element length: the count is the length over it, rounded up [m].
pub const MODAL_BODIES_ELEMENT_LENGTH: Range = Range::new("element_length", "be > 0", "m").gt(0.0);

/// `modal_bodies.damping_ratio`: damping ratio of every mode of the body held at its frame's reference conditions
/// [-].
pub const MODAL_BODIES_DAMPING_RATIO: Range = Range::new("damping_ratio", "be >= 0", "").ge(0.0);

/// `modal_bodies.damping_time`: retardation time tau of stiffness-proportional damping tau K, added to the modal
/// damping: a beam's strain-rate damping of the same damping_time, linearised (mode n gets the ratio tau w_n / 2)
/// [s].
pub const MODAL_BODIES_DAMPING_TIME: Range = Range::new("damping_time", "be >= 0", "s").ge(0.0);

/// `beam_material.youngs_modulus`: Young's modulus E [Pa].
pub const BEAM_MATERIAL_YOUNGS_MODULUS: Range = Range::new("youngs_modulus", "be > 0", "Pa").gt(0.0);

/// `beam_material.density`: density rho [kg/m^3].
pub const BEAM_MATERIAL_DENSITY: Range = Range::new("density", "be > 0", "kg/m^3").gt(0.0);

/// `beam_material.poisson_ratio`: Poisson's ratio nu [-].
pub const BEAM_MATERIAL_POISSON_RATIO: Range = Range::new("poisson_ratio", "lie in (-1, 0.5)", "").gt(-1.0).lt(0.5);

/// `beam_material.shear_modulus`: shear modulus G [Pa].
pub const BEAM_MATERIAL_SHEAR_MODULUS: Range = Range::new("shear_modulus", "be > 0", "Pa").gt(0.0);

/// `material.youngs_modulus`: Young's modulus E [Pa].
pub const MATERIAL_YOUNGS_MODULUS: Range = Range::new("youngs_modulus", "be > 0", "Pa").gt(0.0);

/// `material.poisson_ratio`: Poisson's ratio nu [-].
pub const MATERIAL_POISSON_RATIO: Range = Range::new("poisson_ratio", "lie in (-1, 0.5)", "").gt(-1.0).lt(0.5);

/// `lubrication.viscosity`: dynamic viscosity: "400 cP", "0.4 Pa s" [Pa s].
pub const LUBRICATION_VISCOSITY: Range = Range::new("viscosity", "be > 0", "Pa s").gt(0.0);

/// `lubrication.ambient_pressure`: Reynolds models only: gauge pressure at the bearing ends, not below the
/// cavitation pressure (gauge 0) [Pa].
pub const LUBRICATION_AMBIENT_PRESSURE: Range = Range::new("ambient_pressure", "be >= 0", "Pa").ge(0.0);

/// `lubrication.groove_supply_pressure`: Reynolds models only, reynolds_exact only: a circumferential groove at
/// mid-length held at this pressure (paper 000), not below the cavitation pressure (gauge 0) [Pa].
pub const LUBRICATION_GROOVE_SUPPLY_PRESSURE: Range = Range::new("groove_supply_pressure", "be >= 0", "Pa").ge(0.0);

/// `spatial_bodies.mass`: mass of the body [kg].
pub const SPATIAL_BODIES_MASS: Range = Range::new("mass", "be > 0", "kg").gt(0.0);

/// `joints.clearance_revolute.bearing_radius`: bore radius R_b [m].
pub const JOINTS_CLEARANCE_REVOLUTE_BEARING_RADIUS: Range = Range::new("bearing_radius", "be > 0", "m").gt(0.0);

/// `joints.clearance_revolute.clearance`: radial clearance c = R_b - R_j, smaller than bearing_radius [m].
pub const JOINTS_CLEARANCE_REVOLUTE_CLEARANCE: Range = Range::new("clearance", "be > 0", "m").gt(0.0);

/// `joints.clearance_revolute.length`: axial length of the bearing [m].
pub const JOINTS_CLEARANCE_REVOLUTE_LENGTH: Range = Range::new("length", "be > 0", "m").gt(0.0);

/// `joints.clearance_revolute.onset_velocity_floor`: smallest contact-onset velocity used in the damping term
/// [m/s].
pub const JOINTS_CLEARANCE_REVOLUTE_ONSET_VELOCITY_FLOOR: Range = Range::new("onset_velocity_floor", "be > 0", "m/s").gt(0.0);

/// `joints.clearance_revolute.max_penetration`: penetration at which the run stops as unphysical [m].
pub const JOINTS_CLEARANCE_REVOLUTE_MAX_PENETRATION: Range = Range::new("max_penetration", "be > 0", "m").gt(0.0);

/// `forces.spring_damper.stiffness`: spring stiffness [N/m].
pub const FORCES_SPRING_DAMPER_STIFFNESS: Range = Range::new("stiffness", "be >= 0", "N/m").ge(0.0);

/// `forces.spring_damper.damping`: damping coefficient [N s/m].
pub const FORCES_SPRING_DAMPER_DAMPING: Range = Range::new("damping", "be >= 0", "N s/m").ge(0.0);

/// `forces.spring_damper.free_length`: length at which the spring is relaxed [m].
pub const FORCES_SPRING_DAMPER_FREE_LENGTH: Range = Range::new("free_length", "be >= 0", "m").ge(0.0);

/// `forces.rotational_spring_damper.stiffness`: spring stiffness [N m/rad].
pub const FORCES_ROTATIONAL_SPRING_DAMPER_STIFFNESS: Range = Range::new("stiffness", "be >= 0", "N m/rad").ge(0.0);

/// `forces.rotational_spring_damper.damping`: damping coefficient [N m s/rad].
pub const FORCES_ROTATIONAL_SPRING_DAMPER_DAMPING: Range = Range::new("damping", "be >= 0", "N m s/rad").ge(0.0);

/// `forces.hydraulic_cylinder.piston_area`: piston (cap-side) area A1 = pi D^2/4 [m^2].
pub const FORCES_HYDRAULIC_CYLINDER_PISTON_AREA: Range = Range::new("piston_area", "be > 0", "m^2").gt(0.0);

/// `forces.hydraulic_cylinder.rod_side_area`: rod-side (annulus) area A2 = pi (D^2 - d^2)/4, smaller than
/// piston_area [m^2].
pub const FORCES_HYDRAULIC_CYLINDER_ROD_SIDE_AREA: Range = Range::new("rod_side_area", "be > 0", "m^2").gt(0.0);

/// `forces.hydraulic_cylinder.stroke_length`: stroke S: the rod moves from 0 (fully retracted) to S [m].
pub const FORCES_HYDRAULIC_CYLINDER_STROKE_LENGTH: Range = Range::new("stroke_length", "be > 0", "m").gt(0.0);

/// `forces.hydraulic_cylinder.cap_dead_volume`: volume of the cap chamber at stroke 0 (ports, hoses) [m^3].
pub const FORCES_HYDRAULIC_CYLINDER_CAP_DEAD_VOLUME: Range = Range::new("cap_dead_volume", "be > 0", "m^3").gt(0.0);

/// `forces.hydraulic_cylinder.rod_dead_volume`: volume of the rod chamber at full stroke (ports, hoses) [m^3].
pub const FORCES_HYDRAULIC_CYLINDER_ROD_DEAD_VOLUME: Range = Range::new("rod_dead_volume", "be > 0", "m^3").gt(0.0);

/// `forces.hydraulic_cylinder.initial_stroke`: stroke at the positions given in the model (0: fully retracted), at
/// most stroke_length [m].
pub const FORCES_HYDRAULIC_CYLINDER_INITIAL_STROKE: Range = Range::new("initial_stroke", "be >= 0", "m").ge(0.0);

/// `forces.hydraulic_cylinder.cap_pressure`: gauge pressure of the cap chamber at the start [Pa].
pub const FORCES_HYDRAULIC_CYLINDER_CAP_PRESSURE: Range = Range::new("cap_pressure", "be >= -101325 Pa", "Pa").ge(-101325.0);

/// `forces.hydraulic_cylinder.rod_pressure`: gauge pressure of the rod chamber at the start [Pa].
pub const FORCES_HYDRAULIC_CYLINDER_ROD_PRESSURE: Range = Range::new("rod_pressure", "be >= -101325 Pa", "Pa").ge(-101325.0);

/// `forces.hydraulic_cylinder.bulk_modulus`: effective bulk modulus beta of the liquid, with entrained air and the
/// compliance of barrel and hoses (mineral oil 1.5-1.8 GPa, less in machines) [Pa].
pub const FORCES_HYDRAULIC_CYLINDER_BULK_MODULUS: Range = Range::new("bulk_modulus", "be > 0", "Pa").gt(0.0);

/// `function.speed_ramp.ramp_time`: duration T of the ramp [s].
pub const FUNCTION_SPEED_RAMP_RAMP_TIME: Range = Range::new("ramp_time", "be > 0", "s").gt(0.0);

/// `section.rectangle.width`: width, out of the plane of motion [m].
pub const SECTION_RECTANGLE_WIDTH: Range = Range::new("width", "be > 0", "m").gt(0.0);

/// `section.rectangle.height`: height, in the plane of bending [m].
pub const SECTION_RECTANGLE_HEIGHT: Range = Range::new("height", "be > 0", "m").gt(0.0);

/// `section.circle.diameter`: diameter [m].
pub const SECTION_CIRCLE_DIAMETER: Range = Range::new("diameter", "be > 0", "m").gt(0.0);

/// `section.tube.outer_diameter`: outer diameter [m].
pub const SECTION_TUBE_OUTER_DIAMETER: Range = Range::new("outer_diameter", "be > 0", "m").gt(0.0);

/// `section.tube.inner_diameter`: inner diameter, smaller than outer_diameter [m].
pub const SECTION_TUBE_INNER_DIAMETER: Range = Range::new("inner_diameter", "be > 0", "m").gt(0.0);

/// `section.properties.area`: area A [m^2].
pub const SECTION_PROPERTIES_AREA: Range = Range::new("area", "be > 0", "m^2").gt(0.0);

/// `section.properties.second_moment`: second moment I about the bending axis [m^4].
pub const SECTION_PROPERTIES_SECOND_MOMENT: Range = Range::new("second_moment", "be > 0", "m^4").gt(0.0);

/// `section.properties.shear_factor`: shear factor k (5/6 for a thin rectangle) [-].
pub const SECTION_PROPERTIES_SHEAR_FACTOR: Range = Range::new("shear_factor", "lie in (0, 1]", "").gt(0.0).le(1.0);

/// `section.resultants.axial_stiffness`: E A [N].
pub const SECTION_RESULTANTS_AXIAL_STIFFNESS: Range = Range::new("axial_stiffness", "be > 0", "N").gt(0.0);

/// `section.resultants.shear_stiffness`: k G A [N].
pub const SECTION_RESULTANTS_SHEAR_STIFFNESS: Range = Range::new("shear_stiffness", "be > 0", "N").gt(0.0);

/// `section.resultants.bending_stiffness`: E I [N m^2].
pub const SECTION_RESULTANTS_BENDING_STIFFNESS: Range = Range::new("bending_stiffness", "be > 0", "N m^2").gt(0.0);

/// `section.resultants.mass_per_length`: rho A [kg/m].
pub const SECTION_RESULTANTS_MASS_PER_LENGTH: Range = Range::new("mass_per_length", "be > 0", "kg/m").gt(0.0);

/// `section.resultants.rotary_inertia_per_length`: rho I [kg m].
pub const SECTION_RESULTANTS_ROTARY_INERTIA_PER_LENGTH: Range = Range::new("rotary_inertia_per_length", "be > 0", "kg m").gt(0.0);

/// `spatial_clearance_joints.bore_radius`: bore radius R_b [m].
pub const SPATIAL_CLEARANCE_JOINTS_BORE_RADIUS: Range = Range::new("bore_radius", "be > 0", "m").gt(0.0);

/// `spatial_clearance_joints.clearance`: radial clearance c = R_b - R_j, smaller than bore_radius [m].
pub const SPATIAL_CLEARANCE_JOINTS_CLEARANCE: Range = Range::new("clearance", "be > 0", "m").gt(0.0);

/// `spatial_clearance_joints.bearing_length`: length L of the bore [m].
pub const SPATIAL_CLEARANCE_JOINTS_BEARING_LENGTH: Range = Range::new("bearing_length", "be > 0", "m").gt(0.0);

/// `spatial_clearance_joints.axial_clearance`: flange spacing minus bearing length [m].
pub const SPATIAL_CLEARANCE_JOINTS_AXIAL_CLEARANCE: Range = Range::new("axial_clearance", "be >= 0", "m").ge(0.0);

/// `spatial_clearance_joints.flange_radius`: outer radius of the journal's flanges, larger than bore_radius [m].
pub const SPATIAL_CLEARANCE_JOINTS_FLANGE_RADIUS: Range = Range::new("flange_radius", "be > 0", "m").gt(0.0);

/// `spatial_clearance_joints.face_radius`: outer radius of the bearing's end faces, larger than bore_radius [m].
pub const SPATIAL_CLEARANCE_JOINTS_FACE_RADIUS: Range = Range::new("face_radius", "be > 0", "m").gt(0.0);

/// `spatial_clearance_joints.axial_stiffness`: stiffness of a whole flange ring pressed on its face, applied per
/// unit area of the overlap [N/m].
pub const SPATIAL_CLEARANCE_JOINTS_AXIAL_STIFFNESS: Range = Range::new("axial_stiffness", "be > 0", "N/m").gt(0.0);

/// `spatial_clearance_joints.onset_velocity_floor`: smallest contact-onset velocity used in the damping term [m/s].
pub const SPATIAL_CLEARANCE_JOINTS_ONSET_VELOCITY_FLOOR: Range = Range::new("onset_velocity_floor", "be > 0", "m/s").gt(0.0);

/// `spatial_clearance_joints.max_penetration`: penetration at which the run stops as unphysical [m].
pub const SPATIAL_CLEARANCE_JOINTS_MAX_PENETRATION: Range = Range::new("max_penetration", "be > 0", "m").gt(0.0);

/// `spatial_clearance_joints.mode_impact_speed`: smallest onset approach speed of a radial contact that begins with
/// an impact (motion modes) [m/s].
pub const SPATIAL_CLEARANCE_JOINTS_MODE_IMPACT_SPEED: Range = Range::new("mode_impact_speed", "be > 0", "m/s").gt(0.0);

/// `spatial_clearance_joints.mode_impact_duration`: how long after such an onset the contact counts as impact and
/// rebound (motion modes) [s].
pub const SPATIAL_CLEARANCE_JOINTS_MODE_IMPACT_DURATION: Range = Range::new("mode_impact_duration", "be > 0", "s").gt(0.0);

/// `spatial_clearance_joints.mode_sliding_speed`: sliding speed above which a radial contact is sliding, at or
/// below it sustained (motion modes) [m/s].
pub const SPATIAL_CLEARANCE_JOINTS_MODE_SLIDING_SPEED: Range = Range::new("mode_sliding_speed", "be > 0", "m/s").gt(0.0);

/// `spatial_forces.spring_damper.stiffness`: spring stiffness [N/m].
pub const SPATIAL_FORCES_SPRING_DAMPER_STIFFNESS: Range = Range::new("stiffness", "be >= 0", "N/m").ge(0.0);

/// `spatial_forces.spring_damper.damping`: damping coefficient [N s/m].
pub const SPATIAL_FORCES_SPRING_DAMPER_DAMPING: Range = Range::new("damping", "be >= 0", "N s/m").ge(0.0);

/// `spatial_forces.spring_damper.free_length`: length at which the spring is relaxed [m].
pub const SPATIAL_FORCES_SPRING_DAMPER_FREE_LENGTH: Range = Range::new("free_length", "be >= 0", "m").ge(0.0);

/// `spatial_forces.bushing.stiffness`: translational stiffnesses along x, y, z [N/m].
pub const SPATIAL_FORCES_BUSHING_STIFFNESS: Range = Range::new("stiffness", "be >= 0", "N/m").ge(0.0);

/// `spatial_forces.bushing.damping`: translational damping coefficients [N s/m].
pub const SPATIAL_FORCES_BUSHING_DAMPING: Range = Range::new("damping", "be >= 0", "N s/m").ge(0.0);

/// `spatial_forces.bushing.rotational_stiffness`: rotational stiffnesses about x, y, z [N m/rad].
pub const SPATIAL_FORCES_BUSHING_ROTATIONAL_STIFFNESS: Range = Range::new("rotational_stiffness", "be >= 0", "N m/rad").ge(0.0);

/// `spatial_forces.bushing.rotational_damping`: rotational damping coefficients [N m s/rad].
pub const SPATIAL_FORCES_BUSHING_ROTATIONAL_DAMPING: Range = Range::new("rotational_damping", "be >= 0", "N m s/rad").ge(0.0);

/// `contact.hunt_crossley.restitution`: coefficient of restitution e [-].
pub const CONTACT_HUNT_CROSSLEY_RESTITUTION: Range = Range::new("restitution", "lie in [0, 1]", "").ge(0.0).le(1.0);

/// `contact.lankarani_nikravesh.restitution`: coefficient of restitution e [-].
pub const CONTACT_LANKARANI_NIKRAVESH_RESTITUTION: Range = Range::new("restitution", "lie in [0, 1]", "").ge(0.0).le(1.0);

/// `contact.flores.restitution`: coefficient of restitution e [-].
pub const CONTACT_FLORES_RESTITUTION: Range = Range::new("restitution", "lie in (0, 1]", "").gt(0.0).le(1.0);

/// `contact.gonthier.restitution`: coefficient of restitution e [-].
pub const CONTACT_GONTHIER_RESTITUTION: Range = Range::new("restitution", "lie in (0, 1]", "").gt(0.0).le(1.0);

/// `contact.hu_guo.restitution`: coefficient of restitution e [-].
pub const CONTACT_HU_GUO_RESTITUTION: Range = Range::new("restitution", "lie in (0, 1]", "").gt(0.0).le(1.0);

/// `stiffness.hertz_cylinder.exponent`: exponent n [-].
pub const STIFFNESS_HERTZ_CYLINDER_EXPONENT: Range = Range::new("exponent", "be > 0", "").gt(0.0);

/// `friction.coulomb.coefficient`: friction coefficient mu [-].
pub const FRICTION_COULOMB_COEFFICIENT: Range = Range::new("coefficient", "be >= 0", "").ge(0.0);

/// `friction.coulomb.velocity_tolerance`: regularisation velocity [m/s].
pub const FRICTION_COULOMB_VELOCITY_TOLERANCE: Range = Range::new("velocity_tolerance", "be > 0", "m/s").gt(0.0);

/// `friction.ambrosio.coefficient`: friction coefficient mu [-].
pub const FRICTION_AMBROSIO_COEFFICIENT: Range = Range::new("coefficient", "be >= 0", "").ge(0.0);

/// `friction.ambrosio.v0`: end of the dead band [m/s].
pub const FRICTION_AMBROSIO_V0: Range = Range::new("v0", "be >= 0", "m/s").ge(0.0);

/// `friction.ambrosio.v1`: speed of full friction (> v0) [m/s].
pub const FRICTION_AMBROSIO_V1: Range = Range::new("v1", "be > 0", "m/s").gt(0.0);

/// `friction.threlfall.coefficient`: friction coefficient mu [-].
pub const FRICTION_THRELFALL_COEFFICIENT: Range = Range::new("coefficient", "be >= 0", "").ge(0.0);

/// `friction.threlfall.v0`: speed at which 95 % of mu F_n is reached [m/s].
pub const FRICTION_THRELFALL_V0: Range = Range::new("v0", "be > 0", "m/s").gt(0.0);

/// `friction.stiction.static_coefficient`: static coefficient (>= kinetic_coefficient) [-].
pub const FRICTION_STICTION_STATIC_COEFFICIENT: Range = Range::new("static_coefficient", "be >= 0", "").ge(0.0);

/// `friction.stiction.kinetic_coefficient`: kinetic coefficient [-].
pub const FRICTION_STICTION_KINETIC_COEFFICIENT: Range = Range::new("kinetic_coefficient", "be >= 0", "").ge(0.0);

/// `friction.stiction.stiction_velocity`: velocity at which the static coefficient is reached [m/s].
pub const FRICTION_STICTION_STICTION_VELOCITY: Range = Range::new("stiction_velocity", "be > 0", "m/s").gt(0.0);

/// `friction.stiction.transition_velocity`: velocity from which the kinetic coefficient holds [m/s].
pub const FRICTION_STICTION_TRANSITION_VELOCITY: Range = Range::new("transition_velocity", "be > 0", "m/s").gt(0.0);

/// `transition.flores.lubricated_limit`: eccentricity ratio where the fading starts [-].
pub const TRANSITION_FLORES_LUBRICATED_LIMIT: Range = Range::new("lubricated_limit", "be > 0 and < 1", "").gt(0.0).lt(1.0);

/// `transition.wang_improved.safe_film_thickness`: film thickness where the fading starts [m].
pub const TRANSITION_WANG_IMPROVED_SAFE_FILM_THICKNESS: Range = Range::new("safe_film_thickness", "be > 0", "m").gt(0.0);

/// `seal_friction.lugre_seal.static_force`: static (break-away) force F_S, at least kinetic_force [N].
pub const SEAL_FRICTION_LUGRE_SEAL_STATIC_FORCE: Range = Range::new("static_force", "be > 0", "N").gt(0.0);

/// `seal_friction.lugre_seal.kinetic_force`: kinetic (Coulomb) force F_C, reached in steady sliding [N].
pub const SEAL_FRICTION_LUGRE_SEAL_KINETIC_FORCE: Range = Range::new("kinetic_force", "be > 0", "N").gt(0.0);

/// `seal_friction.lugre_seal.stribeck_velocity`: Stribeck velocity v_S: the friction falls from F_S towards F_C
/// over it [m/s].
pub const SEAL_FRICTION_LUGRE_SEAL_STRIBECK_VELOCITY: Range = Range::new("stribeck_velocity", "be > 0", "m/s").gt(0.0);

/// `seal_friction.lugre_seal.bristle_stiffness`: bristle stiffness sigma0 [N/m].
pub const SEAL_FRICTION_LUGRE_SEAL_BRISTLE_STIFFNESS: Range = Range::new("bristle_stiffness", "be > 0", "N/m").gt(0.0);

/// `seal_friction.lugre_seal.bristle_damping`: bristle damping sigma1 at rest, at most 4 sqrt(2e) F_C /
/// damping_velocity (beyond it the law could create energy) [N s/m].
pub const SEAL_FRICTION_LUGRE_SEAL_BRISTLE_DAMPING: Range = Range::new("bristle_damping", "be >= 0", "N s/m").ge(0.0);

/// `seal_friction.lugre_seal.viscous_coefficient`: viscous coefficient sigma2 [N s/m].
pub const SEAL_FRICTION_LUGRE_SEAL_VISCOUS_COEFFICIENT: Range = Range::new("viscous_coefficient", "be >= 0", "N s/m").ge(0.0);

/// `seal_friction.lugre_seal.damping_velocity`: velocity v_D over which the bristle damping fades [m/s].
pub const SEAL_FRICTION_LUGRE_SEAL_DAMPING_VELOCITY: Range = Range::new("damping_velocity", "be > 0", "m/s").gt(0.0);

/// `seal_friction.lugre_seal.stick_velocity`: stroke rate below which the stick channel reports the seal sticking
/// (it does not change the force) [m/s].
pub const SEAL_FRICTION_LUGRE_SEAL_STICK_VELOCITY: Range = Range::new("stick_velocity", "be > 0", "m/s").gt(0.0);
