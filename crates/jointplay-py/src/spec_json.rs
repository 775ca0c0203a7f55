//! Reading the JSON model description that the Python front end sends.
//!
//! The core's spec has no defaults: every key is given (the front end, from
//! `jointplay.parameters`, sends each value explicitly). A description that
//! cannot be read is reported as problems located like the core's own
//! (`joints[2]`, which Python turns into `joints.B`), not as one message
//! pointing at a column of the JSON text.

use jointplay_core::spec::{BodySpec, DriverSpec, ForceSpec, JointSpec, ModalBodySpec, ModelSpec, PointSpec};
use serde::de::DeserializeOwned;
use serde_json::Value;

/// A located problem: (location, message).
pub type Problem = (String, String);

/// The model description in `text`, or every problem found: each element that cannot be read at
/// its location (`bodies[1]`), otherwise the description as a whole (`model`).
pub fn read_spec(text: &str) -> Result<ModelSpec, Vec<Problem>> {
    let value: Value = serde_json::from_str(text)
        .map_err(|e| vec![("model".to_string(), format!("the model description is not valid JSON: {e}"))])?;
    match serde_json::from_value::<ModelSpec>(value.clone()) {
        Ok(spec) => Ok(spec),
        Err(whole) => {
            let mut problems = Vec::new();
            elements::<PointSpec>(&value, "ground_points", &mut problems);
            elements::<BodySpec>(&value, "bodies", &mut problems);
            elements::<ModalBodySpec>(&value, "modal_bodies", &mut problems);
            elements::<JointSpec>(&value, "joints", &mut problems);
            elements::<DriverSpec>(&value, "drivers", &mut problems);
            elements::<ForceSpec>(&value, "forces", &mut problems);
            if problems.is_empty() {
                problems.push(("model".to_string(), message(&whole)));
            }
            Err(problems)
        }
    }
}

/// The problems of the entries of the list `section`, each at `section[k]`.
fn elements<T: DeserializeOwned>(value: &Value, section: &str, problems: &mut Vec<Problem>) {
    let Some(entries) = value.get(section).and_then(Value::as_array) else { return };
    for (k, entry) in entries.iter().enumerate() {
        if let Err(e) = serde_json::from_value::<T>(entry.clone()) {
            problems.push((format!("{section}[{k}]"), message(&e)));
        }
    }
}

fn message(e: &serde_json::Error) -> String {
    let text = e.to_string();
    if text.starts_with("missing field") {
        format!("{text} (the core reads every key of the model description: there are no defaults on its side)")
    } else {
        text
    }
}
