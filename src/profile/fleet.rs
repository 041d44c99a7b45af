//! Fleets: many devices named once in the profile file and worked on as one, so a technician
//! runs the same commissioning check on 24 presses and gets one table back.
//!
//! ```toml
//! [fleets.presses]
//! devices = ["press1", "press2"]          # profile names (or URLs), in this order
//! [fleets.line2]
//! url = "tcp://10.0.0.{11..34}:502?unit=1" # one `{FIRST..LAST}` range: members line2-11 … line2-34
//! read_only = true                         # any profile key applies to every member of a URL fleet
//! ```
//!
//! This module is the definition, parsed with the profiles (`crate::profile`) because a fleet's
//! keys are a profile's; the concurrent runner is `crate::fleet::run`, the rendering of its
//! results `crate::fleet::report`. A member is always opened through
//! [`crate::session::Session::open_profile`], the same path as `connect PROFILE`, so the profile's write
//! rules and the session's `--read-only` wrap it at the device boundary.

use super::Profile;
use crate::core::{Error, Result};
use crate::msg;
use std::collections::BTreeMap;
use toml::Spanned;

/// The most members one URL range may name (a typo such as `{1..65535}` is refused, not opened).
pub const MAX_MEMBERS: usize = 10_000;

/// How a member is opened.
#[derive(Clone, Debug, PartialEq)]
pub enum Source {
    /// A profile of the same file, by name (checked when the fleet is used: a profile skipped
    /// for a problem fails that member only).
    Profile(String),
    /// A profile made for the member (a URL fleet's expanded address with the fleet's keys,
    /// or a URL in `devices`).
    Made(Profile),
}

/// One device of a fleet.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    pub name: String,
    pub source: Source,
}

/// A named set of devices.
#[derive(Clone, Debug, PartialEq)]
pub struct Fleet {
    pub name: String,
    pub members: Vec<Member>,
    /// How it was written: the `devices` list or the URL pattern (for `devices`).
    pub spec: String,
    /// `file:line` of its section.
    pub origin: String,
}

/// Expands the one `{FIRST..LAST}` range of `pattern` (a URL): each value with the text it
/// stands for. Linear in the pattern's length; refuses a second range, a reversed or empty
/// range and more than [`MAX_MEMBERS`] values.
pub fn expand(pattern: &str) -> std::result::Result<Vec<(u64, String)>, String> {
    let Some(open) = pattern.find('{') else {
        return Err(msg!("fleet-needs-range", example = "{11..34}").into());
    };
    let close = pattern[open..].find('}').map(|c| open + c).ok_or_else(|| msg!("fleet-unclosed-brace").text)?;
    if pattern[close + 1..].contains(['{', '}']) || pattern[..open].contains('}') {
        return Err(msg!("fleet-one-range", form = "{FIRST..LAST}").into());
    }
    let inner = &pattern[open + 1..close];
    let range = format!("{{{inner}}}");
    let (a, b) = inner
        .split_once("..")
        .ok_or_else(|| msg!("fleet-not-range", range = range.as_str(), form = "{FIRST..LAST}").text)?;
    let num =
        |s: &str| s.trim().parse::<u64>().map_err(|_| msg!("fleet-not-number", text = s, range = range.as_str()).text);
    let (a, b) = (num(a)?, num(b)?);
    if b < a {
        return Err(msg!("fleet-backwards", range = range.as_str()).into());
    }
    if b - a >= MAX_MEMBERS as u64 {
        return Err(
            msg!("fleet-too-many", range = range.as_str(), n = (b - a).saturating_add(1), max = MAX_MEMBERS).into()
        );
    }
    let (head, tail) = (&pattern[..open], &pattern[close + 1..]);
    Ok((a..=b).map(|v| (v, format!("{head}{v}{tail}"))).collect())
}

type Bad = (Option<usize>, String);

/// One `[fleets.NAME]` section. `make` builds a member's profile from the section's keys
/// with a given URL (`crate::profile`'s own rules, so a fleet key means what it means in a
/// profile).
pub(crate) fn parse(
    name: &str,
    keys: &BTreeMap<String, Spanned<toml::Value>>,
    origin: &str,
    make: &dyn Fn(&str, &str) -> std::result::Result<Profile, Bad>,
) -> std::result::Result<Fleet, Bad> {
    let at = |v: &Spanned<toml::Value>| Some(v.span().start);
    let mut members = Vec::new();
    let spec;
    match (keys.get("devices"), keys.get("url")) {
        (Some(_), Some(u)) => return Err((at(u), msg!("fleet-devices-or-url").into())),
        (None, None) => {
            return Err((
                None,
                msg!(
                    "fleet-needs-devices",
                    devices = "devices = [\"press1\", …]",
                    url = "url = \"tcp://10.0.0.{11..34}\""
                )
                .into(),
            ))
        }
        (Some(d), None) => {
            let list = match d.get_ref() {
                toml::Value::Array(a) => a.iter().map(|i| i.as_str().map(str::to_string)).collect::<Option<Vec<_>>>(),
                _ => None,
            };
            let list = list.ok_or_else(|| (at(d), msg!("fleet-devices-list").into()))?;
            if list.is_empty() {
                return Err((at(d), msg!("fleet-devices-empty").into()));
            }
            if let Some(k) = keys.keys().find(|k| *k != "devices") {
                return Err((at(&keys[k]), msg!("fleet-devices-rules", key = k.as_str()).into()));
            }
            for (i, item) in list.iter().enumerate() {
                let member = if item.contains(':') {
                    let n = format!("{name}-{}", i + 1);
                    Member { name: n.clone(), source: Source::Made(make(&n, item).map_err(|(_, m)| (at(d), m))?) }
                } else {
                    Member { name: item.clone(), source: Source::Profile(item.clone()) }
                };
                if members.iter().any(|m: &Member| m.name == member.name) {
                    return Err((at(d), msg!("fleet-listed-twice", name = member.name.as_str()).into()));
                }
                members.push(member);
            }
            spec = list.join(", ");
        }
        (None, Some(u)) => {
            let pattern = u.get_ref().as_str().ok_or_else(|| (at(u), msg!("profile-url-not-string").into()))?;
            for (v, url) in expand(pattern).map_err(|m| (at(u), m))? {
                let n = format!("{name}-{v}");
                members.push(Member { name: n.clone(), source: Source::Made(make(&n, &url)?) });
            }
            spec = pattern.to_string();
        }
    }
    Ok(Fleet { name: name.to_string(), members, spec, origin: origin.to_string() })
}

impl Fleet {
    /// The profile a member opens with; an error for a listed profile that is not loaded.
    pub fn profile_of<'a>(&self, m: &'a Member, profiles: &'a crate::profile::Profiles) -> Result<&'a Profile> {
        match &m.source {
            Source::Made(p) => Ok(p),
            Source::Profile(p) => profiles.get(p).ok_or_else(|| {
                let mut e = profiles.unknown(p).device(&m.name);
                e.message = msg!(
                    "fleet-lists-unknown",
                    name = self.name.as_str(),
                    origin = self.origin.as_str(),
                    profile = p.as_str()
                )
                .into();
                e
            }),
        }
    }
}

/// "no fleet named x" with the known names, for errors.
pub fn unknown(profiles: &crate::profile::Profiles, name: &str) -> Error {
    let names: Vec<&str> = profiles.fleets.iter().map(|f| f.name.as_str()).collect();
    let file = profiles.file.as_ref().map(|f| f.display().to_string()).unwrap_or_else(|| "devices.toml".into());
    Error::usage(msg!("fleet-unknown", name = name)).hint(if names.is_empty() {
        msg!(
            "fleet-unknown-define-hint",
            section = format!("[fleets.{name}]"),
            devices = "devices = [\"press1\", …]",
            url = "url = \"tcp://10.0.0.{11..34}\"",
            file = file
        )
    } else {
        msg!("fleet-unknown-list-hint", file = file, list = names.join(", "))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_expands_in_order() {
        let v = expand("tcp://127.0.0.1:{5020..5023}?unit=1").unwrap();
        assert_eq!(v.len(), 4);
        assert_eq!(v[0], (5020, "tcp://127.0.0.1:5020?unit=1".to_string()));
        assert_eq!(v[3].1, "tcp://127.0.0.1:5023?unit=1");
        assert_eq!(expand("tcp://10.0.0.{11..34}").unwrap()[23].1, "tcp://10.0.0.34");
        assert_eq!(expand("tcp://10.0.0.{7..7}").unwrap().len(), 1);
    }

    #[test]
    fn bad_ranges_are_refused_with_a_reason() {
        for (p, says) in [
            ("tcp://10.0.0.1", "needs one range"),
            ("tcp://10.0.0.{1..3", "without `}`"),
            ("tcp://10.0.{1..2}.{1..3}", "only one"),
            ("tcp://10.0.0.{5..1}", "backwards"),
            ("tcp://10.0.0.{a..3}", "not a number"),
            ("tcp://10.0.0.{1-3}", "not a range"),
            ("tcp://h:{1..65535}", "at most"),
            ("t:{0..18446744073709551615}", "at most"),
            ("tcp://h:}{1..2}", "only one"),
        ] {
            let e = expand(p).unwrap_err();
            assert!(e.contains(says), "{p}: {e}");
        }
    }

    fn load(text: &str) -> crate::profile::Profiles {
        crate::profile::Profiles::parse(text, std::path::Path::new("/etc/devices.toml"))
    }

    #[test]
    fn a_url_fleet_gives_every_member_the_fleets_keys() {
        let p = load("[fleets.line]\nurl = \"tcp://10.0.0.{11..12}:502\"\nunit = 3\nallow = [\"VW100\"]\n");
        assert!(p.problems.is_empty(), "{:?}", p.problems);
        let f = p.fleet("line").unwrap();
        let names: Vec<&str> = f.members.iter().map(|m| m.name.as_str()).collect();
        assert_eq!(names, ["line-11", "line-12"]);
        let Source::Made(m) = &f.members[1].source else { panic!("{f:?}") };
        assert_eq!(m.url, "tcp://10.0.0.12:502?unit=3");
        assert_eq!(m.allow, Some(vec!["VW100".to_string()]));
        assert_eq!(f.origin, "/etc/devices.toml:1");
    }

    #[test]
    fn a_list_fleet_names_profiles_and_urls() {
        let p = load("[devices.a]\nurl = \"sim:K205-16DT\"\n[fleets.mixed]\ndevices = [\"a\", \"sim:K209M-56DT\"]\n");
        let f = p.fleet("mixed").unwrap();
        assert_eq!(f.members[0].source, Source::Profile("a".into()));
        assert_eq!(f.members[1].name, "mixed-2");
        assert!(p.fleet("nope").unwrap_err().hint.clone().unwrap().contains("mixed"));
    }

    #[test]
    fn bad_fleets_are_skipped_with_their_line() {
        let p = load(concat!(
            "[fleets.both]\ndevices = [\"a\"]\nurl = \"tcp://h:{1..2}\"\n",
            "[fleets.none]\nread_only = true\n",
            "[fleets.twice]\ndevices = [\"a\", \"a\"]\n",
            "[fleets.keyed]\ndevices = [\"a\"]\nread_only = true\n",
            "[fleets.empty]\ndevices = []\n",
        ));
        assert!(p.fleets.is_empty(), "{:?}", p.fleets);
        let shown: Vec<String> = p.problems.iter().map(|x| x.to_string()).collect();
        assert_eq!(shown.len(), 5, "{shown:?}");
        assert!(
            shown[0].starts_with("/etc/devices.toml:3: fleet `both` skipped: give `devices` or `url`"),
            "{shown:?}"
        );
        assert!(shown.iter().any(|s| s.contains("`a` is listed twice")), "{shown:?}");
        assert!(shown.iter().any(|s| s.contains("takes its rules from each profile")), "{shown:?}");
    }
}
