//! The keys of every table of the model description, as the core's
//! deserialisers read them: the front end's registry of parameters
//! (`python/jointplay/parameters.py`) is compared with this list by
//! `tests/test_parameter_boundary.py`, so that a key is named the same on both
//! sides of the language boundary.
//!
//! The keys are not written out a second time here: they are read from
//! serde's own messages, which list the fields a table expects when it meets
//! an unknown one ("unknown field `x`, expected one of `a`, `b`") and the
//! variants of a tagged table when it meets an unknown tag.

use serde::de::DeserializeOwned;
use serde_json::{json, Map, Value};

use super::{
    BeamMaterialSpec, BeamMeshSpec, BeamPointSpec, BeamSectionSpec, BeamSpec, BodySpec, ContactSpec, DriverSpec, ForceSpec, FrictionSpec, FunctionSpec,
    JointSpec, LubricationSpec, MaterialSpec, ModalBodySpec, ModalPointSpec, ModalStructureSpec, ModelSpec, PointSpec, ReynoldsSpec, SealFrictionSpec,
    SensorSpec, SparseMatrixSpec, SpatialBodySpec, SpatialForceSpec, SpatialClearanceJointSpec, SpatialJointSpec, SpatialPointSpec, StiffnessSpec, TransitionSpec,
};

/// A key no table has, to make a table list the keys it expects.
const PROBE: &str = "\u{1}probe";

/// One key of a table: its name and whether it may be left out (it is an
/// `Option`, none when absent).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TableKey {
    /// The key as written in the description.
    pub key: String,
    /// True when the key may be left out or null (its default: none).
    pub optional: bool,
}

/// The keys of one table of the description, by an id naming the table, or
/// its family and variant: `"bodies"`, `"forces.spring_damper"`, `"contact.flores"`.
pub type TableKeys = (String, Vec<TableKey>);

/// Every table of the model description with its keys, in the order of its
/// declaration; the tag of a tagged table (`type`, `law`, `kind`) is not among them.
pub fn table_keys() -> Result<Vec<TableKeys>, String> {
    let mut out = Vec::new();
    plain::<ModelSpec>("model", &mut out)?;
    plain::<PointSpec>("point", &mut out)?;
    plain::<BodySpec>("bodies", &mut out)?;
    tagged::<JointSpec>("joints", "type", &mut out)?;
    plain::<MaterialSpec>("material", &mut out)?;
    tagged::<ContactSpec>("contact", "law", &mut out)?;
    tagged::<StiffnessSpec>("stiffness", "law", &mut out)?;
    tagged::<FrictionSpec>("friction", "law", &mut out)?;
    plain::<LubricationSpec>("lubrication", &mut out)?;
    tagged::<TransitionSpec>("transition", "law", &mut out)?;
    plain::<ReynoldsSpec>("reynolds", &mut out)?;
    plain::<DriverSpec>("drivers", &mut out)?;
    tagged::<FunctionSpec>("function", "kind", &mut out)?;
    tagged::<ForceSpec>("forces", "type", &mut out)?;
    plain::<SealFrictionSpec>("seal_friction", &mut out)?;
    plain::<BeamSpec>("beams", &mut out)?;
    plain::<BeamPointSpec>("beam_point", &mut out)?;
    plain::<BeamMeshSpec>("beam_mesh", &mut out)?;
    tagged::<BeamSectionSpec>("section", "type", &mut out)?;
    plain::<BeamMaterialSpec>("beam_material", &mut out)?;
    tagged::<SensorSpec>("sensors", "type", &mut out)?;
    plain::<ModalBodySpec>("modal_bodies", &mut out)?;
    tagged::<ModalStructureSpec>("structure", "from", &mut out)?;
    plain::<SparseMatrixSpec>("sparse_matrix", &mut out)?;
    plain::<ModalPointSpec>("modal_point", &mut out)?;
    plain::<SpatialBodySpec>("spatial_bodies", &mut out)?;
    plain::<SpatialPointSpec>("spatial_point", &mut out)?;
    plain::<SpatialJointSpec>("spatial_joints", &mut out)?;
    tagged::<SpatialForceSpec>("spatial_forces", "type", &mut out)?;
    plain::<SpatialClearanceJointSpec>("spatial_clearance_joints", &mut out)?;
    Ok(out)
}

/// The keys of the untagged table `T`.
fn plain<T: DeserializeOwned>(id: &str, out: &mut Vec<TableKeys>) -> Result<(), String> {
    out.push((id.to_string(), keys::<T>(Map::new())?));
    Ok(())
}

/// The keys of each variant of the table `T` tagged by `tag`, as `"{family}.{variant}"`.
fn tagged<T: DeserializeOwned>(family: &str, tag: &str, out: &mut Vec<TableKeys>) -> Result<(), String> {
    let message = refusal::<T>(json!({ tag: PROBE }))?;
    let variants = listed(&message, "unknown variant").ok_or_else(|| format!("{family}: no list of variants in {message:?}"))?;
    for variant in variants {
        let mut base = Map::new();
        base.insert(tag.to_string(), Value::String(variant.clone()));
        out.push((format!("{family}.{variant}"), keys::<T>(base)?));
    }
    Ok(())
}

/// The keys `T` expects besides those of `base` (its tag), each with whether it may be null.
fn keys<T: DeserializeOwned>(base: Map<String, Value>) -> Result<Vec<TableKey>, String> {
    let mut probe = base.clone();
    probe.insert(PROBE.to_string(), Value::from(0));
    let names = match serde_json::from_value::<T>(Value::Object(probe)) {
        Ok(_) => Vec::new(), // a variant without keys (serde lets it ignore unknown ones)
        Err(e) => listed(&e.to_string(), "unknown field").ok_or_else(|| format!("no list of keys in {:?}", e.to_string()))?,
    };
    Ok(names.into_iter().map(|key| TableKey { optional: accepts_null::<T>(&base, &key), key }).collect())
}

/// Whether `T` reads `key: null` (an `Option`): a key that may not be null is
/// refused for its type before any other key is missed.
fn accepts_null<T: DeserializeOwned>(base: &Map<String, Value>, key: &str) -> bool {
    let mut given = base.clone();
    given.insert(key.to_string(), Value::Null);
    match serde_json::from_value::<T>(Value::Object(given)) {
        Ok(_) => true,
        Err(e) => !e.to_string().starts_with("invalid type: null"),
    }
}

/// serde's message refusing `value` as a `T`.
fn refusal<T: DeserializeOwned>(value: Value) -> Result<String, String> {
    match serde_json::from_value::<T>(value) {
        Ok(_) => Err("a probe was accepted".to_string()),
        Err(e) => Ok(e.to_string()),
    }
}

/// The names serde's message `{what} `x`, expected ...` lists: "one of `a`, `b`",
/// "`a` or `b`", "`a`", or none ("there are no fields").
fn listed(message: &str, what: &str) -> Option<Vec<String>> {
    let rest = message.strip_prefix(what)?;
    if rest.contains("there are no") {
        return Some(Vec::new());
    }
    let (_, expected) = rest.split_once(", expected ")?;
    Some(expected.split('`').skip(1).step_by(2).map(str::to_string).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn keys_of(id: &str) -> Vec<(String, bool)> {
        let tables = table_keys().unwrap();
        let (_, keys) = tables.iter().find(|(name, _)| name == id).unwrap_or_else(|| panic!("no table {id}"));
        keys.iter().map(|k| (k.key.clone(), k.optional)).collect()
    }

    fn owned(keys: &[(&str, bool)]) -> Vec<(String, bool)> {
        keys.iter().map(|(k, optional)| (k.to_string(), *optional)).collect()
    }

    #[test]
    fn a_struct_variant_lists_its_fields_in_order_with_the_optional_ones() {
        assert_eq!(keys_of("joints.revolute"), owned(&[("name", false), ("first", false), ("second", false)]));
        assert_eq!(keys_of("transition.wang_improved"), owned(&[("safe_film_thickness", true)]));
    }

    #[test]
    fn a_newtype_variant_lists_the_fields_of_its_struct() {
        let keys = keys_of("joints.clearance_revolute");
        assert_eq!(keys.first(), Some(&("name".to_string(), false)));
        assert!(keys.contains(&("length".to_string(), true)) && keys.contains(&("lubrication".to_string(), true)));
        assert!(keys.contains(&("bearing_radius".to_string(), false)));
    }

    #[test]
    fn a_variant_without_fields_has_no_keys() {
        assert_eq!(keys_of("contact.hertz"), Vec::new());
        assert_eq!(keys_of("friction.none"), Vec::new());
    }

    #[test]
    fn every_variant_of_a_tagged_table_is_listed() {
        let tables = table_keys().unwrap();
        let contact: Vec<&str> = tables.iter().filter_map(|(id, _)| id.strip_prefix("contact.")).collect();
        assert_eq!(contact, ["hertz", "hunt_crossley", "lankarani_nikravesh", "flores", "gonthier", "hu_guo"]);
    }

    #[test]
    fn a_table_with_one_key_and_with_two_keys_are_read() {
        assert_eq!(keys_of("contact.flores"), owned(&[("restitution", false)]));
        assert_eq!(keys_of("function.constant_rate"), owned(&[("initial", false), ("rate", false)]));
    }
}
