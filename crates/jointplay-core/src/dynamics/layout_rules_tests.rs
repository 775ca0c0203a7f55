//! The folders of `dynamics/` are the stages of the pipeline, and imports run
//! one way: a file imports from its own folder (`super::`, any depth) or from
//! a folder of a lower stage, written `crate::dynamics::<folder>::...`. The two
//! folders of stage 1 (the compiler and the formulations) do not import each
//! other; nothing inside `dynamics/` goes through the root re-exports
//! (`crate::dynamics::Model`) or climbs with `super::super`; a source file
//! directly in `dynamics/` other than `mod.rs` belongs to no stage and is
//! refused. Test files (`tests.rs`, `*_tests.rs`) and everything from a
//! file's first `#[cfg(test)]` line on are exempt.

use std::fs;
use std::path::Path;

/// The stage folders of `dynamics/` and their place in the pipeline (0 first).
const STAGES: [(&str, u8); 6] = [
    ("model", 0),
    ("compiler", 1),
    ("formulations", 1),
    ("starts", 2),
    ("outputs", 3),
    ("simulation", 4),
];

/// The stage of folder `name`, `None` when it is no stage folder.
fn stage(name: &str) -> Option<u8> {
    STAGES.iter().find(|(folder, _)| *folder == name).map(|&(_, s)| s)
}

/// Whether a test file, exempt from the rule.
fn is_test_file(path: &str) -> bool {
    let name = path.rsplit('/').next().unwrap_or(path);
    name == "tests.rs" || name.ends_with("_tests.rs")
}

/// The text of a file up to its first `#[cfg(test)]` line (tests are exempt).
fn code_part(text: &str) -> impl Iterator<Item = (usize, &str)> {
    text.lines().enumerate().take_while(|(_, line)| !line.trim_start().starts_with("#[cfg(test)]")).map(|(k, line)| (k + 1, line))
}

/// The identifier at the start of `rest` (letters, digits, `_`).
fn leading_identifier(rest: &str) -> &str {
    let end = rest.find(|c: char| !(c.is_ascii_alphanumeric() || c == '_')).unwrap_or(rest.len());
    &rest[..end]
}

/// Every breach of the rule in the file at `path` (relative to `dynamics/`,
/// with `/` separators) whose text is `text`, as `"path:line: what"`.
fn violations(path: &str, text: &str) -> Vec<String> {
    let mut found = Vec::new();
    if is_test_file(path) {
        return found;
    }
    let components: Vec<&str> = path.split('/').collect();
    // directly in dynamics/: only the root module (the public names) and tests
    let folder = if components.len() > 1 { Some(components[0]) } else { None };
    if folder.is_none() && path != "mod.rs" {
        found.push(format!("{path}: a source file outside the stage folders (put it in the folder of its stage)"));
        return found;
    }
    let stage_root = components.len() == 2 && components[1] == "mod.rs";
    for (number, line) in code_part(text) {
        let mut breach = |what: String| found.push(format!("{path}:{number}: {what}: `{}`", line.trim()));
        if line.contains("super::super") {
            breach("`super::super` (write `crate::dynamics::<folder>::...`)".to_string());
        }
        if stage_root && line.contains("super::") {
            breach("`super::` in a stage folder's mod.rs reaches the root re-exports".to_string());
        }
        let Some(from) = folder else { continue };
        let Some(from_stage) = stage(from) else {
            breach(format!("folder `{from}` is no stage of the pipeline"));
            continue;
        };
        for (at, _) in line.match_indices("crate::dynamics::") {
            let rest = &line[at + "crate::dynamics::".len()..];
            let to = leading_identifier(rest);
            match stage(to) {
                _ if to.is_empty() => breach("an import through the root of `dynamics` (name the folder)".to_string()),
                None => breach(format!("`crate::dynamics::{to}` is a root re-export (name the folder it comes from)")),
                Some(_) if to == from => {}
                Some(to_stage) if to_stage < from_stage => {}
                Some(to_stage) if to_stage == from_stage => {
                    breach(format!("`{from}/` and `{to}/` are both stage {from_stage} and do not import each other"))
                }
                Some(to_stage) => breach(format!("`{from}/` (stage {from_stage}) imports `{to}/`, a later stage ({to_stage})")),
            }
        }
    }
    found
}

/// The `.rs` files under `dir` with their paths relative to `root`.
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<(String, String)>) {
    let mut entries: Vec<_> = fs::read_dir(dir).expect("dynamics/ is readable").map(|e| e.expect("a directory entry").path()).collect();
    entries.sort();
    for path in entries {
        if path.is_dir() {
            rust_files(root, &path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            let relative = path.strip_prefix(root).expect("under dynamics/").components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect::<Vec<_>>().join("/");
            out.push((relative, fs::read_to_string(&path).expect("a source file is text")));
        }
    }
}

#[test]
fn imports_in_dynamics_run_from_later_stages_to_earlier_ones_only() {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src/dynamics"));
    let mut files = Vec::new();
    rust_files(root, root, &mut files);
    // the walk saw the whole folder: every stage folder, and files in each
    for (folder, _) in STAGES {
        let prefix = format!("{folder}/");
        assert!(files.iter().any(|(path, _)| path.starts_with(&prefix) && !is_test_file(path)), "no source file in {folder}/");
    }
    let checked = files.iter().filter(|(path, _)| !is_test_file(path)).count();
    assert!(checked > 40, "only {checked} source files under dynamics/");
    let found: Vec<String> = files.iter().flat_map(|(path, text)| violations(path, text)).collect();
    assert!(found.is_empty(), "imports against the pipeline's order:\n{}", found.join("\n"));
}

#[test]
fn the_rule_names_each_kind_of_breach() {
    let upward = "use crate::dynamics::simulation::simulate::SimulationOptions;\n";
    let found = violations("model/mechanism.rs", upward);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].starts_with("model/mechanism.rs:1: `model/` (stage 0) imports `simulation/`, a later stage (4)"), "{}", found[0]);

    let sibling = "use crate::dynamics::formulations::workspace::Workspace;\n";
    let found = violations("compiler/compile.rs", sibling);
    assert!(found.len() == 1 && found[0].contains("both stage 1"), "{found:?}");

    let root = "use crate::dynamics::Model;\nuse crate::dynamics::{assemble, compile};\n";
    let found = violations("starts/assembly.rs", root);
    assert_eq!(found.len(), 2, "{found:?}");
    assert!(found[0].contains("root re-export") && found[1].contains("through the root"), "{found:?}");

    let climbing = "use super::super::model::mechanism::Model;\n";
    assert_eq!(violations("formulations/absolute/equations.rs", climbing).len(), 1);
    assert_eq!(violations("outputs/mod.rs", "use super::Model;\n").len(), 1);

    let flat = violations("elements.rs", "use crate::dynamics::model::mechanism::Model;\n");
    assert!(flat.len() == 1 && flat[0].contains("outside the stage folders"), "{flat:?}");
    assert_eq!(violations("mod.rs", "pub use model::mechanism::Model;\n"), Vec::<String>::new());

    // allowed: own folder, lower stages, and anything in tests
    let allowed = "use super::equations::update_frames;\nuse crate::dynamics::model::mechanism::Model;\nuse crate::dynamics::formulations::workspace::Workspace;\nuse crate::dynamics::starts::assembly::assemble;\n#[cfg(test)]\nuse crate::dynamics::simulate;\n";
    assert_eq!(violations("outputs/trajectory.rs", allowed), Vec::<String>::new());
    assert_eq!(violations("outputs/extrema_tests.rs", upward), Vec::<String>::new());
}
