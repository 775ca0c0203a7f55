//! The spec has no defaults: checked on the descriptions the Python front end sends for every
//! example (`tests/fixtures/specs/*.json`, pinned by `tests/test_spec_fixtures.py`).

use super::ModelSpec;
use serde_json::Value;
use std::path::PathBuf;

/// The `spec` of each fixture, by file name.
fn fixtures() -> Vec<(String, Value)> {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/fixtures/specs");
    let mut out: Vec<(String, Value)> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|entry| entry.unwrap().path())
        .filter(|path| path.extension().is_some_and(|ext| ext == "json"))
        .map(|path| {
            let doc: Value = serde_json::from_str(&std::fs::read_to_string(&path).unwrap()).unwrap();
            (path.file_name().unwrap().to_string_lossy().into_owned(), doc["spec"].clone())
        })
        .collect();
    out.sort_by(|a, b| a.0.cmp(&b.0));
    assert!(out.len() >= 10, "fixtures in {}: {}", dir.display(), out.len());
    out
}

/// Same keys everywhere, numbers equal as f64 (`0` and `0.0` alike).
fn same(a: &Value, b: &Value, at: &str) -> Result<(), String> {
    match (a, b) {
        (Value::Object(x), Value::Object(y)) => {
            // (an `Option` left out and one given as null are the same: none)
            let given = |m: &'_ serde_json::Map<String, Value>| m.iter().filter(|(_, v)| !v.is_null()).map(|(k, _)| k.clone()).collect::<Vec<_>>();
            let (kx, ky) = (given(x), given(y));
            let (mut sx, mut sy) = (kx.clone(), ky.clone());
            sx.sort();
            sy.sort();
            if sx != sy {
                return Err(format!("{at}: keys {kx:?} vs {ky:?}"));
            }
            x.iter().filter(|(_, v)| !v.is_null()).try_for_each(|(k, v)| same(v, &y[k], &format!("{at}.{k}")))
        }
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => {
            x.iter().zip(y).enumerate().try_for_each(|(k, (u, v))| same(u, v, &format!("{at}[{k}]")))
        }
        // a planar description's 2-vector of a point or of gravity is read as a 3-vector with z = 0
        (Value::Array(x), Value::Array(y)) if x.len() == 2 && y.len() == 3 && y[2].as_f64() == Some(0.0) => {
            same(a, &Value::Array(y[..2].to_vec()), at)
        }
        (Value::Number(x), Value::Number(y)) if x.as_f64() == y.as_f64() => Ok(()),
        _ if a == b => Ok(()),
        _ => Err(format!("{at}: {a} vs {b}")),
    }
}

#[test]
fn the_front_end_sends_every_key_the_core_reads() {
    // read and written back, a description gives exactly what was sent: no key was left to the core
    for (name, sent) in fixtures() {
        let spec: ModelSpec = serde_json::from_value(sent.clone()).unwrap_or_else(|e| panic!("{name}: {e}"));
        let read = serde_json::to_value(&spec).unwrap();
        same(&sent, &read, "spec").unwrap_or_else(|e| panic!("{name}: {e}"));
    }
}

/// The path of every key of `value` (keys of objects inside arrays by index).
fn key_paths(value: &Value, path: &mut Vec<PathStep>, out: &mut Vec<Vec<PathStep>>) {
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                path.push(PathStep::Key(k.clone()));
                out.push(path.clone());
                key_paths(v, path, out);
                path.pop();
            }
        }
        Value::Array(items) => {
            for (i, v) in items.iter().enumerate() {
                path.push(PathStep::Index(i));
                key_paths(v, path, out);
                path.pop();
            }
        }
        _ => {}
    }
}

#[derive(Clone, Debug)]
enum PathStep {
    Key(String),
    Index(usize),
}

/// `value` with the key at `path` removed (`replacement` None) or given another value.
fn edited(value: &Value, path: &[PathStep], replacement: Option<Value>) -> Value {
    let mut out = value.clone();
    let mut node = &mut out;
    for step in &path[..path.len() - 1] {
        node = match step {
            PathStep::Key(k) => &mut node[k.as_str()],
            PathStep::Index(i) => &mut node[*i],
        };
    }
    let PathStep::Key(last) = &path[path.len() - 1] else { unreachable!("paths end at a key") };
    let map = node.as_object_mut().unwrap();
    match replacement {
        None => map.remove(last),
        Some(v) => map.insert(last.clone(), v),
    };
    out
}

#[test]
fn a_key_left_out_is_an_error_unless_it_means_none() {
    // the core has no default values: a key left out is an error, except a key that may be null
    // (an Option), whose absence means what null means, none
    let mut checked = 0;
    for (name, sent) in fixtures() {
        let mut paths = Vec::new();
        key_paths(&sent, &mut Vec::new(), &mut paths);
        for path in paths {
            let absent = serde_json::from_value::<ModelSpec>(edited(&sent, &path, None));
            let null = serde_json::from_value::<ModelSpec>(edited(&sent, &path, Some(Value::Null)));
            match (absent, null) {
                (Err(_), Err(_)) => {}
                (Ok(a), Ok(b)) if a == b => {}
                (Ok(_), _) => panic!("{name}: {path:?} left out, and the core read a value other than none"),
                (Err(e), Ok(_)) => panic!("{name}: {path:?} may be null but not left out: {e}"),
            }
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked} keys");
}

#[test]
fn a_missing_key_is_named_by_the_error() {
    let (_, sent) = fixtures().into_iter().find(|(name, _)| name == "py_flores_slider_crank_dry.json").unwrap();
    let joint = sent["joints"].as_array().unwrap().iter().position(|j| j["type"] == "clearance_revolute").unwrap();
    let path = [PathStep::Key("joints".into()), PathStep::Index(joint), PathStep::Key("onset_velocity_floor".into())];
    let rest = edited(&sent, &path, None);
    let error = serde_json::from_value::<ModelSpec>(rest).unwrap_err().to_string();
    assert!(error.contains("missing field `onset_velocity_floor`"), "{error}");
}
