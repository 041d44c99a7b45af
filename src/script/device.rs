//! Devices as Lua objects: `plc.SMB67 = 0x85`, `local v = plc.VW100`,
//! `plc:set{…}`, `plc:get("VW100", "VD104")`, and every helper of [`super::bridge::BRIDGE`]
//! as a method.
//!
//! A handle holds a device *name* and is resolved on every call, so a closed device gives a
//! clear error instead of a dangling object. Field access is the hot path (≥ 1 M writes/s
//! against the simulator): operands are parsed once per handle and cached (the cache is
//! dropped when the name comes to mean another device), and values go straight to
//! `Session::write_values`/`read_values`, never through command text.

use super::api::{self, index, with_shell};
use super::bridge::{self, BRIDGE};
use super::error::raise;
use crate::core::{DataType, Error, Operand, Result, Value as V};
use crate::shell::Shell;
use mlua::{Lua, MetaMethod, MultiValue, Table, UserData, UserDataMethods, Value};
use std::collections::HashMap;

/// A device in Lua.
pub struct Handle {
    name: String,
    /// What the name meant when the cache was filled (url, model, its tag names).
    ident: (String, String, usize),
    cache: HashMap<Box<[u8]>, Operand>,
}

impl Handle {
    pub fn new(name: &str) -> Handle {
        Handle { name: name.to_string(), ident: (String::new(), String::new(), 0), cache: HashMap::new() }
    }

    /// Resolves the name now; drops the cache if the name now means another device.
    fn resolve(&mut self, sh: &mut Shell) -> Result<usize> {
        let i = index(sh, &self.name)?;
        // Ready first (`crate::pending`): a state file taken, a link tried again.
        sh.session.ready(i)?;
        let e = &sh.session.entries()[i];
        let model = &e.device.info().model;
        // A tag file loaded since (`plc:tags_load`) changes what a name means.
        let names = std::sync::Arc::as_ptr(&e.names) as usize;
        if e.url != self.ident.0 || *model != self.ident.1 || names != self.ident.2 {
            self.cache.clear();
            self.ident = (e.url.clone(), model.clone(), names);
        }
        Ok(i)
    }

    /// One operand by name, parsed once.
    fn operand(&mut self, sh: &Shell, i: usize, key: &[u8]) -> Result<Operand> {
        if let Some(op) = self.cache.get(key) {
            return Ok(*op);
        }
        let text = std::str::from_utf8(key).map_err(|_| Error::usage(crate::msg!("script-operand-not-text")))?;
        // Names first (`plc.Conveyor_Run`, `plc["Мотор_1_Пуск"]`): the session's one parser.
        let ops = sh.session.parse_on(i, text).map_err(|e| e.device(&self.name))?;
        let [op] = ops[..] else {
            return Err(Error::usage(crate::msg!("script-field-many-operands", text = text, count = ops.len()))
                .device(&self.name)
                .hint(crate::msg!("script-hint-read-range", device = self.name.as_str(), text = text)));
        };
        self.cache.insert(key.into(), op);
        Ok(op)
    }

    /// `plc:close()`, `plc.staus`: a lower-case word is a method name, never an operand (operands
    /// have digits: `VW0`, `vw0`). Says there is no such method and names the nearest ones.
    fn not_a_method(&self, key: &[u8], family: &str) -> Option<Error> {
        let word = std::str::from_utf8(key).ok()?;
        let looks_like_method = word.chars().any(|c| c.is_ascii_lowercase())
            && word.chars().all(|c| c.is_ascii_alphabetic() || c == '_')
            && !word.is_empty();
        if !looks_like_method {
            return None;
        }
        let mut all: Vec<&str> = METHODS.to_vec();
        all.extend(BRIDGE.iter().filter(|b| b.applies_to(family)).map(|b| b.method));
        let mut near: Vec<(usize, &str)> = all
            .iter()
            .map(|m| (crate::core::text::edit_distance(word, m), *m))
            .filter(|(d, _)| *d <= (word.len() / 3).max(1))
            .collect();
        near.sort();
        let hint = if near.is_empty() {
            crate::msg!("script-hint-methods", methods = all.join(", "), device = self.name.as_str())
        } else {
            let names: Vec<String> = near.iter().take(3).map(|(_, m)| format!("{}:{m}()", self.name)).collect();
            let at = |k: usize| names.get(k).cloned().unwrap_or_default();
            crate::msg!("script-hint-did-you-mean-method", count = names.len(), a = at(0), b = at(1), c = at(2))
        };
        Some(
            Error::usage(crate::msg!("script-no-method", device = self.name.as_str(), word = word))
                .device(&self.name)
                .hint(hint),
        )
    }

    /// Field write: `plc.VW100 = 5`.
    fn write(&mut self, lua: &Lua, key: &[u8], v: &Value) -> mlua::Result<()> {
        with_shell(lua, |sh| {
            let i = self.resolve(sh)?;
            let op = self.operand(sh, i, key)?;
            let val = to_value(sh, i, &op, v)?;
            sh.session.write_values(i, &[(op, val)])
        })
    }

    /// Field read: `plc.VW100`.
    fn read(&mut self, lua: &Lua, key: &[u8]) -> mlua::Result<Value> {
        let v = with_shell(lua, |sh| {
            let i = self.resolve(sh)?;
            // Not an operand (servo objects are lower-case words): maybe a mistyped method.
            let op = self
                .operand(sh, i, key)
                .map_err(|e| self.not_a_method(key, sh.session.entries()[i].device.info().family).unwrap_or(e))?;
            sh.session.read_values(i, &[op])
        })?;
        Ok(from_value(v[0]))
    }

    /// `plc:get("VW100", "VD104", "VW0..VW4")`: every value, in order.
    fn get(&mut self, lua: &Lua, names: Vec<String>) -> mlua::Result<MultiValue> {
        let values = with_shell(lua, |sh| {
            let i = self.resolve(sh)?;
            let mut ops = Vec::new();
            for n in &names {
                match self.operand(sh, i, n.as_bytes()) {
                    Ok(op) => ops.push(op),
                    Err(_) => ops.extend(sh.session.parse_on(i, n).map_err(|e| e.device(&self.name))?),
                }
            }
            sh.session.read_values(i, &ops)
        })?;
        Ok(values.into_iter().map(from_value).collect())
    }

    /// `plc:set{…}`, `plc:set({"A", 1}, {"B", 2})`, `plc:set("A", 1, "B", 2)`,
    /// `plc:set("A=16#85, B=2")`. Everything is checked before anything is written.
    fn set(&mut self, lua: &Lua, args: MultiValue) -> mlua::Result<()> {
        let args: Vec<Value> = args.into_iter().collect();
        if let [Value::String(s)] = &args[..] {
            let line = format!("set {}", s.to_str()?);
            api::exec_on(lua, Some(&self.name), &line)?;
            return Ok(());
        }
        let mut pairs: Vec<(Vec<u8>, Value)> = Vec::new();
        let pair = |t: &Table| -> mlua::Result<(Vec<u8>, Value)> {
            let k: mlua::LuaString = t.get(1)?;
            Ok((k.as_bytes().to_vec(), t.get(2)?))
        };
        match &args[..] {
            [Value::Table(t)] => {
                for v in t.sequence_values::<Table>() {
                    pairs.push(pair(&v?)?);
                }
                let mut keyed = Vec::new();
                for p in t.pairs::<Value, Value>() {
                    if let (Value::String(k), v) = p? {
                        keyed.push((k.as_bytes().to_vec(), v));
                    }
                }
                // Lua tables are unordered: keyed items go in name order, after list items.
                keyed.sort_by(|a, b| a.0.cmp(&b.0));
                pairs.extend(keyed);
            }
            [Value::Table(_), ..] => {
                for a in &args {
                    let Value::Table(t) = a else {
                        return Err(raise(Error::usage(crate::msg!("script-set-pairs-only"))));
                    };
                    pairs.push(pair(t)?);
                }
            }
            [Value::String(_), ..] => {
                if !args.len().is_multiple_of(2) {
                    return Err(raise(Error::usage(crate::msg!("script-set-odd-arguments", count = args.len()))));
                }
                for c in args.chunks(2) {
                    let Value::String(k) = &c[0] else {
                        return Err(raise(Error::usage(crate::msg!("script-set-names-strings"))));
                    };
                    pairs.push((k.as_bytes().to_vec(), c[1].clone()));
                }
            }
            _ => {
                return Err(raise(
                    Error::usage(crate::msg!("script-set-needs-values")).hint(
                        "plc:set{SMB67=0x85}, plc:set({\"SMB67\", 0x85}, …), plc:set(\"SMB67\", 0x85), plc:set(\"SMB67=16#85\")",
                    ),
                ))
            }
        }
        with_shell(lua, |sh| {
            let i = self.resolve(sh)?;
            let mut items = Vec::with_capacity(pairs.len());
            for (k, v) in &pairs {
                let op = self.operand(sh, i, k)?;
                items.push((op, to_value(sh, i, &op, v)?));
            }
            sh.session.write_values(i, &items)
        })
    }
}

/// A Lua value for operand `op`: numbers, booleans, or a literal string (`"16#85"`).
fn to_value(sh: &Shell, i: usize, op: &Operand, v: &Value) -> Result<V> {
    let space = sh.session.entries()[i].device.operands();
    let named = |e: Error| e.operand(space.name(op)).device(sh.session.entries()[i].name.clone());
    Ok(match v {
        Value::Integer(n) => V::Int(*n),
        Value::Number(f) if op.dtype == DataType::Real => V::Real(*f),
        Value::Number(f) if f.fract() == 0.0 && f.abs() < 9.2e18 => V::Int(*f as i64),
        Value::Number(f) => V::Real(*f),
        Value::Boolean(b) => V::Bool(*b),
        Value::String(s) => space.value(op, &s.to_string_lossy()).map_err(named)?,
        other => {
            return Err(named(Error::new(
                crate::core::ErrorKind::Value,
                crate::msg!("script-cannot-write-value", kind = other.type_name()),
            )))
        }
    })
}

fn from_value(v: V) -> Value {
    match v {
        V::Int(i) => Value::Integer(i),
        V::Real(r) => Value::Number(r),
        V::Bool(b) => Value::Boolean(b),
    }
}

/// The methods every device handle has besides the bridge's (see `add_methods`).
const METHODS: &[&str] = &["get", "set", "name", "info", "tags_load"];

impl UserData for Handle {
    fn add_methods<M: UserDataMethods<Self>>(m: &mut M) {
        m.add_meta_method_mut(MetaMethod::Index, |lua, this, key: mlua::LuaString| this.read(lua, &key.as_bytes()));
        m.add_meta_method_mut(MetaMethod::NewIndex, |lua, this, (key, v): (mlua::LuaString, Value)| {
            this.write(lua, &key.as_bytes(), &v)
        });
        m.add_meta_method(MetaMethod::ToString, |lua, this, ()| {
            let what = with_shell(lua, |sh| {
                Ok(match index(sh, &this.name) {
                    Ok(i) => {
                        let info = sh.session.entries()[i].device.info();
                        format!("{} {}", info.family, info.model)
                    }
                    Err(_) => "closed".to_string(),
                })
            })?;
            Ok(format!("device {} ({what})", this.name))
        });
        m.add_method_mut("get", |lua, this, names: mlua::Variadic<String>| this.get(lua, names.into_iter().collect()));
        m.add_method_mut("set", |lua, this, args: MultiValue| this.set(lua, args));
        m.add_method("name", |_, this, ()| Ok(this.name.clone()));
        m.add_method("info", |lua, this, ()| {
            let j = with_shell(lua, |sh| {
                let i = index(sh, &this.name)?;
                let e = &sh.session.entries()[i];
                let mut j = serde_json::to_value(e.device.info()).unwrap_or_default();
                j["name"] = e.name.clone().into();
                j["url"] = e.url.clone().into();
                Ok(j)
            })?;
            api::json_to_lua(lua, &j)
        });
        // `plc:tags_load("press1.csv")`: the device's tag names (`crate::names`), a path
        // relative to the working directory as `io.open` reads it; returns how many.
        m.add_method("tags_load", |lua, this, file: String| {
            with_shell(lua, |sh| {
                let i = index(sh, &this.name)?;
                sh.session.load_tags(i, std::path::Path::new(&file))
            })
        });
        for b in BRIDGE {
            m.add_method(b.method, move |lua, this, args: MultiValue| {
                bridge::call(lua, &this.name, b, &args.into_iter().collect::<Vec<_>>())
            });
        }
    }
}

/// A handle for an open device.
pub fn handle(lua: &Lua, name: &str) -> mlua::Result<mlua::AnyUserData> {
    with_shell(lua, |sh| index(sh, name).map(|_| ()))?;
    lua.create_userdata(Handle::new(name))
}

/// Makes every open device whose name is a Lua identifier a global (`plc`, `servo`), unless
/// the script already uses that global for something else.
pub fn refresh_globals(lua: &Lua) -> mlua::Result<()> {
    let names: Vec<String> = with_shell(lua, |sh| Ok(sh.session.entries().iter().map(|e| e.name.clone()).collect()))?;
    let g = lua.globals();
    for n in names {
        let ident = n.chars().next().is_some_and(|c| c.is_ascii_alphabetic() || c == '_')
            && n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_');
        if !ident {
            continue;
        }
        match g.raw_get::<Value>(n.as_str())? {
            Value::Nil => g.raw_set(n.as_str(), Handle::new(&n))?,
            Value::UserData(u) if u.is::<Handle>() => {}
            _ => {}
        }
    }
    Ok(())
}

/// `plcsh.device(name)`, `plcsh.connect(url [, name])`.
pub fn register(lua: &Lua) -> mlua::Result<()> {
    let p: Table = lua.globals().get("plcsh")?;
    p.set("device", lua.create_function(|lua, name: String| handle(lua, &name))?)?;
    p.set(
        "connect",
        lua.create_function(|lua, (url, name): (String, Option<String>)| {
            let name = with_shell(lua, |sh| {
                let name = match name {
                    Some(n) => n,
                    None => {
                        // A servo URL (`kinco:`, `sim-servo:`) is named `servo`, anything else `plc`;
                        // taken names get a number (`plc2`).
                        let scheme = url.split(':').next().unwrap_or("").to_ascii_lowercase();
                        let servo = scheme.contains("servo") || scheme == "kinco";
                        let base = if servo { "servo".to_string() } else { "plc".to_string() };
                        (1..)
                            .map(|k| if k == 1 { base.clone() } else { format!("{base}{k}") })
                            .find(|c| sh.session.index(c).is_err())
                            .unwrap_or(base)
                    }
                };
                sh.session.open(&name, &url)?;
                Ok(name)
            })?;
            handle(lua, &name)
        })?,
    )?;
    Ok(())
}
