//! Device URLs: the schemes plcsh knows (`sim:`, `tcp://`, `rtu:`, `kinco:`, …), the family
//! each names, and opening a device from its URL ([`open_url`]) — one list, which a new family
//! extends. Below the session (which keeps the open devices) and the profiles (which check a
//! profile's URL against an offline twin), so both open devices through it.

use crate::core::platform::words::port;
use crate::core::url::DeviceUrl;
use crate::core::{Clock, Device, Error, Result};

/// URL schemes with what they open, for completion and hints, and the family and kind
/// (simulated or not) each names: `(prefix, meaning, family, simulated)`. Keep in step with
/// [`open_url`] (a test checks that every scheme listed here is one `open_url` knows).
pub static SCHEMES: &[(&str, &str, &str, bool)] = &[
    ("sim:", "in-process K2 simulator: sim:MODEL", "k2", true),
    ("kinco:", concat!("Kinco servo drive on a serial port: kinco:", port!(), "?id=1&baud=38400"), "servo", false),
    ("sim-servo:", "in-process Kinco servo simulator: sim-servo:?id=1", "servo", true),
    ("umpk:", concat!("UMPK8/UMPK16 teaching PLC on a serial port: umpk:", port!(), "?baud=57600"), "umpk", false),
    ("sim-umpk:", "in-process UMPK simulator: sim-umpk:UMPK16", "umpk", true),
    ("tcp://", "K2 over Modbus TCP: tcp://HOST:502?unit=1&model=K204ET-16DT", "k2", false),
    ("rtu:", concat!("K2 over Modbus RTU: rtu:", port!(), "?baud=115200&unit=1&model=K205-16DT"), "k2", false),
    ("rtu+tcp://", "K2 through an RTU-over-TCP gateway: rtu+tcp://HOST:PORT?unit=1", "k2", false),
    ("fx:", concat!("FX PLC on its programming port: fx:", port!(), "?model=FX2N"), "fx", false),
    ("fxlink:", concat!("FX PLC over the computer link: fxlink:", port!(), "?station=0&pc=FF&wait=0"), "fx", false),
    ("sim-fx:", "in-process FX simulator: sim-fx:FX2N[?protocol=link]", "fx", true),
];

/// The URL parameters of the in-process K2 simulator (`sim:MODEL`).
pub const K2_SIM_PARAMS: &[&str] = &["model", "program"];

/// The family a device URL names and whether it is a simulator, by its base scheme
/// (`rtu+tcp://…` is `rtu`); `None` for an unknown scheme or a bare profile name.
pub fn url_family(url: &str) -> Option<(&'static str, bool)> {
    let (scheme, _) = url.split_once(':')?;
    let base = scheme.split('+').next().unwrap_or(scheme);
    SCHEMES
        .iter()
        .find(|(prefix, ..)| prefix.trim_end_matches("//").trim_end_matches(':') == base)
        .map(|&(_, _, family, simulated)| (family, simulated))
}

/// Opens a device from its URL. Every scheme plcsh knows is listed here.
pub fn open_url(url: &str, clock: &Clock) -> Result<Box<dyn Device>> {
    let mut u = DeviceUrl::parse(url)?;
    if matches!(u.base_scheme(), "tcp" | "rtu" | "fx" | "fxlink" | "umpk") {
        u = u.without("control");
    }
    match u.base_scheme() {
        "sim" => {
            u.expect_params(K2_SIM_PARAMS)?;
            let model = u.param("model").unwrap_or(&u.target);
            let mut d = crate::k2::open_sim(model, clock.clone())?;
            if let Some(p) = u.param("program") {
                d.set_option("program", p)?; // an IL program running in the simulated CPU
            }
            Ok(d)
        }
        "kinco" => crate::servo::driver::open_serial(&u),
        "sim-servo" => crate::servo::driver::open_sim(&u, clock),
        "tcp" | "rtu" => crate::k2::open_wire(&u),
        "fx" => crate::fx::driver::open_port(&u),
        "fxlink" => crate::fx::driver::open_link(&u),
        "sim-fx" => crate::fx::driver::open_sim(&u, clock),
        "umpk" => crate::umpk::driver::open_serial(&u),
        "sim-umpk" => crate::umpk::driver::open_sim(&u, clock),
        other => Err(Error::usage(crate::msg!("profile-unknown-scheme", scheme = other, url = url))
            .hint(crate::msg!("schemes-known-hint"))),
    }
}
