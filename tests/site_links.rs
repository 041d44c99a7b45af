//! The user guide as readers get it: built with mdBook into a site, every relative link of
//! every page leads to a file of the site and every `#anchor` to an element of that page. The
//! Markdown check (tests/doc_examples.rs) cannot see what only the site breaks: a link to a
//! repository folder, a page left out of docs/SUMMARY.md, a heading id mdBook spells its way.
//! Needs mdBook (.ci/run installs it into target/tools); without it the test says
//! `skipped: needs mdbook` (under CI it fails).

mod common;
use common::*;
use std::collections::{BTreeSet, HashMap};
use std::path::{Path, PathBuf};
use std::process::Command;

/// mdBook: the copy .ci/run installs, else one on PATH.
fn mdbook() -> Option<PathBuf> {
    let local = Path::new(env!("CARGO_MANIFEST_DIR")).join("target/tools/bin/mdbook");
    let works = |p: &Path| Command::new(p).arg("--version").output().is_ok_and(|o| o.status.success());
    if works(&local) {
        return Some(local);
    }
    works(Path::new("mdbook")).then(|| PathBuf::from("mdbook"))
}

fn html_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            html_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "html") {
            out.push(p);
        }
    }
}

/// The values of an attribute (`href`, `src`, `id`) in a page.
fn attributes(html: &str, name: &str) -> Vec<String> {
    let pat = format!(" {name}=\"");
    html.match_indices(&pat)
        .filter_map(|(k, _)| {
            let rest = &html[k + pat.len()..];
            rest.find('"').map(|end| rest[..end].to_string())
        })
        .collect()
}

/// `%20` and the like, as a browser decodes a link's path.
fn percent_decoded(s: &str) -> String {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'%' && i + 2 < b.len() {
            if let Ok(v) = u8::from_str_radix(&s[i + 1..i + 3], 16) {
                out.push(v);
                i += 3;
                continue;
            }
        }
        out.push(b[i]);
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

#[test]
fn every_link_of_the_built_site_resolves() {
    let Some(mdbook) = mdbook() else {
        assert!(std::env::var_os("CI").is_none(), "CI must install mdbook (.ci/run)");
        skipped("mdbook (cargo install mdbook --version 0.4.40, as .ci/run does)");
        return;
    };
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let site = std::env::temp_dir().join(format!("plcsh-site-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&site);
    let o = Command::new(&mdbook).arg("build").arg(root.join("docs")).arg("-d").arg(&site).output().unwrap();
    let log = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
    assert!(o.status.success(), "mdbook build failed:\n{log}");
    assert!(!log.contains("[WARN]") && !log.contains("[ERROR]"), "mdbook build reported problems:\n{log}");

    let mut pages = Vec::new();
    html_files(&site, &mut pages);
    let mut ids: HashMap<PathBuf, BTreeSet<String>> = HashMap::new();
    let mut ids_of = |p: &Path| -> BTreeSet<String> {
        ids.entry(p.to_path_buf())
            .or_insert_with(|| attributes(&std::fs::read_to_string(p).unwrap_or_default(), "id").into_iter().collect())
            .clone()
    };
    let (mut checked, mut bad) = (0, Vec::new());
    for page in &pages {
        let html = std::fs::read_to_string(page).unwrap();
        let name = page.strip_prefix(&site).unwrap().display().to_string();
        let mut links = attributes(&html, "href");
        links.extend(attributes(&html, "src"));
        for link in links {
            if link.contains("://") || link.starts_with("mailto:") || link.starts_with("javascript:") {
                continue;
            }
            checked += 1;
            let (path, frag) = link.split_once('#').unwrap_or((&link, ""));
            let path = percent_decoded(path.split('?').next().unwrap());
            // `/…` is the site's root (the 404 page's `<base href="/">`).
            let mut target = match path.strip_prefix('/') {
                Some(from_root) => site.join(from_root),
                None if path.is_empty() => page.clone(),
                None => page.parent().unwrap().join(&path),
            };
            if target.is_dir() {
                target = target.join("index.html");
            }
            if !target.is_file() {
                bad.push(format!("{name}: {link} (no such file on the site)"));
                continue;
            }
            if !frag.is_empty() && target.extension().is_some_and(|x| x == "html") {
                let frag = percent_decoded(frag);
                if !ids_of(&target).contains(&frag) {
                    bad.push(format!("{name}: {link} (no element with id `{frag}`)"));
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(&site);
    println!("site links: {checked} checked in {} pages", pages.len());
    assert!(bad.is_empty(), "{} broken links on the built site:\n{}", bad.len(), bad.join("\n"));
    assert!(checked > 200, "only {checked} links: did the site build?");
}
