//! One way down: the layers of `src/` and the rule that keeps them (docs/development.md,
//! "Layers"). Each top-level module has a layer; a `crate::` path in a module may name its own
//! layer or a lower one, never a higher one, and a device family never names another family.
//! Inside one folder, the files (other than `mod.rs`) never depend on each other in a cycle;
//! nor do the folders and files of one folder, the top-level modules among them, counting every
//! file inside a folder as that folder's (a layer's modules may use each other, one way only).
//!
//! The test reads the source as text (comments and `#[cfg(test)]` code aside: a test may build
//! a whole session to exercise a family) and names every line that breaks the rule. Exceptions
//! still standing are listed in [`EXCEPTIONS`], each with its reason; a listed exception that no
//! longer occurs fails the test too, so the list only shrinks.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The layers, lowest first. A module may use modules of its own layer and of layers below.
const LAYERS: &[(&str, &[&str])] = &[
    ("core", &["core"]),
    ("base", &["engine", "paths", "signals", "plot", "tags"]),
    ("families", &["k2", "servo", "umpk", "fx"]),
    (
        "devices",
        &["wiring", "guard", "snapshot", "pending", "names", "session", "profile", "confine", "output", "schemes"],
    ),
    ("services", &["record", "dataset", "report"]),
    ("front ends", &["fleet", "lab", "script", "shell", "publish"]),
    ("cli", &["cli", "fuzzing"]),
];

/// Modules of one layer that must not name each other: the device families.
const FAMILIES: &[&str] = &["k2", "servo", "umpk", "fx"];

/// Modules that must name no device family at all (design guide: "core and the guard name no
/// family"): a new family is added without touching them.
const FAMILY_NEUTRAL: &[&str] = &["core", "engine", "guard", "pending", "tags"];

/// `(file, module it names, reason)`: imports that still break the rule, each with its reason.
const EXCEPTIONS: &[(&str, &str, &str)] = &[];

/// Sibling-file cycles that still stand: `(folder, reason)`; a listed folder without a cycle
/// fails the test, as a stale entry of [`EXCEPTIONS`] does.
const CYCLE_EXCEPTIONS: &[(&str, &str)] = &[];

#[path = "support/source_tree.rs"]
mod source_tree;
use source_tree::rust_files;

fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|(_, mods)| mods.contains(&module))
}

/// The file's code without comments and without its `#[cfg(test)]` modules (which run to the
/// end of the file by this project's convention), as (line number, text).
fn code_lines(text: &str) -> Vec<(usize, String)> {
    let mut out = Vec::new();
    let mut in_block_comment = false;
    let lines: Vec<&str> = text.lines().collect();
    for (i, raw) in lines.iter().enumerate() {
        let t = raw.trim_start();
        if t.starts_with("#[cfg(test)]") {
            let next = lines.get(i + 1).map(|l| l.trim_start()).unwrap_or("");
            if next.starts_with("mod ") && next.ends_with('{') {
                break;
            }
            if next.starts_with("mod ") && next.ends_with(';') {
                continue; // a test module in its own file (that file is skipped by name)
            }
        }
        if in_block_comment {
            if let Some(end) = t.find("*/") {
                in_block_comment = false;
                out.push((i + 1, t[end + 2..].to_string()));
            }
            continue;
        }
        if t.starts_with("//") {
            continue;
        }
        if t.starts_with("/*") && !t.contains("*/") {
            in_block_comment = true;
            continue;
        }
        // `//` after code starts a comment, unless inside a string (URLs like tcp://).
        let code = raw
            .match_indices("//")
            .map(|(p, _)| p)
            .find(|&p| raw[..p].matches('"').count() % 2 == 0)
            .map_or(*raw, |p| &raw[..p]);
        out.push((i + 1, code.to_string()));
    }
    out
}

/// The top-level modules a line names through `crate::`, grouped imports included.
fn crate_refs(line: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(p) = rest.find("crate::") {
        let after = &rest[p + "crate::".len()..];
        if let Some(group) = after.strip_prefix('{') {
            let end = group.find('}').unwrap_or(group.len());
            for item in group[..end].split(',') {
                let name: String = item.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
                if !name.is_empty() {
                    out.push(name);
                }
            }
        } else {
            let name: String = after.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
            if !name.is_empty() {
                out.push(name);
            }
        }
        rest = &rest[p + "crate::".len()..];
    }
    out
}

/// The top-level module of a file under src/ (`src/k2/sim/mod.rs` → `k2`, `src/guard.rs` →
/// `guard`), or `None` for the crate roots and the binaries.
fn module_of(rel: &Path) -> Option<String> {
    let mut parts = rel.iter().map(|p| p.to_string_lossy().into_owned());
    let first = parts.next()?;
    if first == "bin" || first == "lib.rs" || first == "main.rs" {
        return None;
    }
    Some(first.trim_end_matches(".rs").to_string())
}

fn is_test_file(p: &Path) -> bool {
    p.file_name().is_some_and(|n| n.to_string_lossy().ends_with("tests.rs"))
}

fn src() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

#[test]
fn every_module_has_a_layer() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut missing = BTreeSet::new();
    for f in &files {
        if let Some(m) = module_of(f.strip_prefix(src()).unwrap()) {
            if layer_of(&m).is_none() {
                missing.insert(m);
            }
        }
    }
    assert!(missing.is_empty(), "modules with no layer in LAYERS: {missing:?}");
}

#[test]
fn no_module_names_a_higher_layer_or_another_family() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    files.sort();
    let mut found: Vec<(String, String, String)> = Vec::new();
    let mut seen_exceptions = BTreeSet::new();
    for f in &files {
        let rel = f.strip_prefix(src()).unwrap();
        let Some(module) = module_of(rel) else { continue };
        if is_test_file(f) {
            continue;
        }
        let Some(own) = layer_of(&module) else { continue };
        let text = std::fs::read_to_string(f).unwrap();
        let rel_text = format!("src/{}", rel.to_string_lossy().replace('\\', "/"));
        for (n, line) in code_lines(&text) {
            for target in crate_refs(&line) {
                if target == module {
                    continue;
                }
                let Some(theirs) = layer_of(&target) else { continue };
                let across = FAMILIES.contains(&module.as_str()) && FAMILIES.contains(&target.as_str());
                let neutral = FAMILY_NEUTRAL.contains(&module.as_str()) && FAMILIES.contains(&target.as_str());
                if theirs <= own && !across && !neutral {
                    continue;
                }
                if EXCEPTIONS.iter().any(|(file, m, _)| *file == rel_text && *m == target) {
                    seen_exceptions.insert((rel_text.clone(), target.clone()));
                    continue;
                }
                let why = if across {
                    "another family".to_string()
                } else if neutral {
                    format!("`{module}` is family-neutral")
                } else {
                    format!("layer `{}` above `{}`", LAYERS[theirs].0, LAYERS[own].0)
                };
                found.push((format!("{rel_text}:{n}"), target.clone(), format!("{why}: {}", line.trim())));
            }
        }
    }
    let report: Vec<String> = found.iter().map(|(at, m, why)| format!("{at} names crate::{m} ({why})")).collect();
    assert!(report.is_empty(), "imports against the layer order:\n{}", report.join("\n"));
    let stale: Vec<String> = EXCEPTIONS
        .iter()
        .filter(|(f, m, _)| !seen_exceptions.contains(&(f.to_string(), m.to_string())))
        .map(|(f, m, _)| format!("{f} → {m}"))
        .collect();
    assert!(stale.is_empty(), "exceptions that no longer occur (remove them): {stale:?}");
}

/// The sibling files a file in `folder` names (`super::x`, `crate::folder::x`, `use super::{x, y}`).
fn sibling_refs(line: &str, crate_path: &str, siblings: &BTreeSet<String>) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for prefix in ["super::".to_string(), format!("crate::{crate_path}::")] {
        let mut start = 0;
        while let Some(found) = line[start..].find(prefix.as_str()) {
            let p = start + found;
            // `super::super::…` names the folder above: not a sibling.
            let after = &line[p + prefix.len()..];
            let before_ok = prefix != "super::" || !line[..p].ends_with("super::");
            let names: Vec<String> = if let Some(group) = after.strip_prefix('{') {
                let end = group.find('}').unwrap_or(group.len());
                group[..end]
                    .split(',')
                    .map(|i| i.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect())
                    .collect()
            } else {
                vec![after.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect()]
            };
            if before_ok && !after.starts_with("super::") {
                for n in names {
                    if siblings.contains(&n) {
                        out.insert(n);
                    }
                }
            }
            start = p + prefix.len();
        }
    }
    out
}

#[test]
fn no_cycles_between_the_files_of_a_folder() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    let mut folders: BTreeMap<PathBuf, Vec<PathBuf>> = BTreeMap::new();
    for f in files {
        if f.file_name().is_some_and(|n| n == "mod.rs" || n == "lib.rs" || n == "main.rs") || is_test_file(&f) {
            continue;
        }
        folders.entry(f.parent().unwrap().to_path_buf()).or_default().push(f);
    }
    let mut cycles = Vec::new();
    let mut cyclic = BTreeSet::new();
    for (folder, files) in &folders {
        let rel = folder.strip_prefix(src()).unwrap_or(Path::new(""));
        if rel.as_os_str().is_empty() || rel.starts_with("bin") {
            continue; // top-level modules are layered by the test above
        }
        let crate_path = rel.to_string_lossy().replace(['/', '\\'], "::");
        let name = |f: &Path| f.file_stem().unwrap().to_string_lossy().into_owned();
        let mut siblings: BTreeSet<String> = files.iter().map(|f| name(f)).collect();
        // A sibling folder with a mod.rs is a sibling module too.
        for e in std::fs::read_dir(folder).unwrap() {
            let p = e.unwrap().path();
            if p.join("mod.rs").exists() {
                siblings.insert(p.file_name().unwrap().to_string_lossy().into_owned());
            }
        }
        let mut edges: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for f in files {
            let text = std::fs::read_to_string(f).unwrap();
            let me = name(f);
            let mut to = BTreeSet::new();
            for (_, line) in code_lines(&text) {
                to.extend(sibling_refs(&line, &crate_path, &siblings));
            }
            to.remove(&me);
            edges.insert(me, to);
        }
        // Depth-first search for a cycle among the files.
        fn visit(
            n: &str,
            edges: &BTreeMap<String, BTreeSet<String>>,
            stack: &mut Vec<String>,
            done: &mut BTreeSet<String>,
            out: &mut Vec<Vec<String>>,
        ) {
            if let Some(pos) = stack.iter().position(|s| s == n) {
                out.push(stack[pos..].to_vec());
                return;
            }
            if done.contains(n) {
                return;
            }
            stack.push(n.to_string());
            for m in edges.get(n).into_iter().flatten() {
                visit(m, edges, stack, done, out);
            }
            stack.pop();
            done.insert(n.to_string());
        }
        let mut found = Vec::new();
        let mut done = BTreeSet::new();
        for n in edges.keys() {
            visit(n, &edges, &mut Vec::new(), &mut done, &mut found);
        }
        let folder_text = format!("src/{}", rel.to_string_lossy().replace('\\', "/"));
        if !found.is_empty() {
            cyclic.insert(folder_text.clone());
        }
        if !found.is_empty() && !CYCLE_EXCEPTIONS.iter().any(|(f, _)| *f == folder_text) {
            for c in found {
                cycles.push(format!("{folder_text}: {} → {}", c.join(" → "), c[0]));
            }
        }
    }
    assert!(cycles.is_empty(), "files of one folder that depend on each other in a cycle:\n{}", cycles.join("\n"));
    let stale: Vec<&str> = CYCLE_EXCEPTIONS.iter().map(|(f, _)| *f).filter(|f| !cyclic.contains(*f)).collect();
    assert!(stale.is_empty(), "cycle exceptions that no longer occur (remove them): {stale:?}");
}

/// A cycle in `edges`, if there is one (depth-first search).
fn find_cycle(edges: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        n: &str,
        edges: &BTreeMap<String, BTreeSet<String>>,
        stack: &mut Vec<String>,
        done: &mut BTreeSet<String>,
    ) -> Option<Vec<String>> {
        if let Some(pos) = stack.iter().position(|s| s == n) {
            return Some(stack[pos..].to_vec());
        }
        if !done.insert(n.to_string()) {
            return None;
        }
        stack.push(n.to_string());
        for m in edges.get(n).into_iter().flatten() {
            if let Some(c) = visit(m, edges, stack, done) {
                return Some(c);
            }
        }
        stack.pop();
        None
    }
    let mut done = BTreeSet::new();
    edges.keys().find_map(|n| visit(n, edges, &mut Vec::new(), &mut done))
}

/// The children of every folder under src/ (its files and sub-folders, the crate root's being
/// the top-level modules) never name each other in a cycle: an arrow goes from a child to
/// another when any file inside the first names the second by its `crate::` path (for the top
/// level, any `crate::MODULE`). So a session that opens profiles never has a profile open a
/// session, and the shell that hands lines to Lua is not also a module Lua's engine hands back to.
#[test]
fn no_cycles_between_the_modules_and_folders_of_a_folder() {
    let mut files = Vec::new();
    rust_files(&src(), &mut files);
    files.sort();
    let root = src();
    // Folder (as a crate path, "" for the root) → child → children it names.
    let mut graphs: BTreeMap<String, BTreeMap<String, BTreeSet<String>>> = BTreeMap::new();
    let mut children: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    let parts_of = |f: &Path| -> Vec<String> {
        let rel = f.strip_prefix(&root).unwrap();
        rel.iter().map(|p| p.to_string_lossy().trim_end_matches(".rs").to_string()).collect()
    };
    for f in &files {
        let parts = parts_of(f);
        if matches!(parts[0].as_str(), "bin" | "lib" | "main") {
            continue;
        }
        for depth in 0..parts.len() {
            let child = &parts[depth];
            if child == "mod" {
                continue;
            }
            children.entry(parts[..depth].join("::")).or_default().insert(child.clone());
        }
    }
    for f in &files {
        let parts = parts_of(f);
        if matches!(parts[0].as_str(), "bin" | "lib" | "main") || is_test_file(f) {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        let code: Vec<String> = code_lines(&text).into_iter().map(|(_, l)| l).collect();
        // For each folder above the file: the child the file is in, and the children it names.
        for depth in 0..parts.len() - 1 {
            let folder = parts[..depth].join("::");
            let me = &parts[depth];
            let Some(kids) = children.get(&folder) else { continue };
            let prefix = if folder.is_empty() { "crate::".to_string() } else { format!("crate::{folder}::") };
            for line in &code {
                let mut rest = line.as_str();
                while let Some(p) = rest.find(prefix.as_str()) {
                    let after = &rest[p + prefix.len()..];
                    let names: Vec<String> = match after.strip_prefix('{') {
                        Some(group) => group[..group.find('}').unwrap_or(group.len())]
                            .split(',')
                            .map(|i| i.trim().chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect())
                            .collect(),
                        None => vec![after.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect()],
                    };
                    for n in names {
                        if kids.contains(&n) && n != *me {
                            graphs.entry(folder.clone()).or_default().entry(me.clone()).or_default().insert(n);
                        }
                    }
                    rest = &rest[p + prefix.len()..];
                }
            }
        }
    }
    let mut cycles = Vec::new();
    for (folder, edges) in &graphs {
        if let Some(c) = find_cycle(edges) {
            let at = if folder.is_empty() { "src".to_string() } else { format!("src/{}", folder.replace("::", "/")) };
            cycles.push(format!("{at}: {} → {}", c.join(" → "), c[0]));
        }
    }
    assert!(cycles.is_empty(), "modules of one folder that name each other in a cycle:\n{}", cycles.join("\n"));
}

#[test]
fn a_cycle_is_found() {
    let edges = |pairs: &[(&str, &str)]| {
        let mut m: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
        for (a, b) in pairs {
            m.entry(a.to_string()).or_default().insert(b.to_string());
        }
        m
    };
    assert_eq!(find_cycle(&edges(&[("shell", "script"), ("script", "lab")])), None);
    let c = find_cycle(&edges(&[("lab", "script"), ("script", "shell"), ("shell", "lab")])).unwrap();
    assert_eq!(c.len(), 3, "{c:?}");
}

#[test]
fn the_reader_sees_through_comments_and_groups() {
    assert_eq!(crate_refs("use crate::{fx::driver as fx, k2::driver as k2};"), vec!["fx", "k2"]);
    assert_eq!(crate_refs("let x = crate::core::value::mask(3);"), vec!["core"]);
    let lines = code_lines("use a;\n// crate::k2::x\nlet u = \"tcp://h\"; // crate::fx\n#[cfg(test)]\nmod tests {\nuse crate::session;\n}\n");
    let all: Vec<String> = lines.iter().flat_map(|(_, l)| crate_refs(l)).collect();
    assert!(all.is_empty(), "{all:?}");
    let sib: BTreeSet<String> = ["plc", "memory"].iter().map(|s| s.to_string()).collect();
    let r = sibling_refs("use super::{plc::Plc, memory};", "fx", &sib);
    assert_eq!(r.len(), 2);
    assert!(sibling_refs("use super::super::plc;", "fx", &sib).is_empty());
}
