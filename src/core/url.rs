//! Device URLs: `sim:K205-16DT`, `tcp://127.0.0.1:502?unit=1&model=K204ET-16DT`,
//! `rtu:/dev/ttyUSB0?baud=115200`, `kinco:/dev/ttyUSB1?id=1`. Split once here; each
//! family interprets its own scheme and parameters.

use super::error::{Error, Result};

/// A split device URL.
#[derive(Clone, Debug, PartialEq)]
pub struct DeviceUrl {
    pub scheme: String,
    /// Everything between the scheme and the query (`127.0.0.1:502`, `/dev/ttyUSB0`, `K205-16DT`).
    pub target: String,
    pub params: Vec<(String, String)>,
    pub text: String,
}

impl DeviceUrl {
    pub fn parse(text: &str) -> Result<DeviceUrl> {
        let t = text.trim();
        let Some(colon) = t.find(':') else {
            return Err(Error::usage(crate::msg!("url-not-url", text = t)).hint(crate::msg!(
                "url-not-url-hint",
                rtu = concat!("rtu:", crate::core::platform::words::port!(), "?baud=115200"),
                kinco = concat!("kinco:", crate::core::platform::words::port!(), "?id=1")
            )));
        };
        let scheme = t[..colon].to_ascii_lowercase();
        let mut rest = &t[colon + 1..];
        if let Some(r) = rest.strip_prefix("//") {
            rest = r;
        }
        let (target, query) = match rest.find('?') {
            Some(q) => (&rest[..q], &rest[q + 1..]),
            None => (rest, ""),
        };
        let mut params = Vec::new();
        for pair in query.split('&').filter(|p| !p.is_empty()) {
            let (k, v) = pair.split_once('=').unwrap_or((pair, ""));
            params.push((k.to_ascii_lowercase(), v.to_string()));
        }
        Ok(DeviceUrl { scheme, target: target.to_string(), params, text: t.to_string() })
    }

    /// The scheme without its carrier: `kinco` for `kinco+rfc2217`, `rtu` for `rtu+tcp`.
    /// The family is chosen by it; the carrier is the transport layer's business.
    pub fn base_scheme(&self) -> &str {
        self.scheme.split('+').next().unwrap_or("")
    }

    pub fn param(&self, key: &str) -> Option<&str> {
        self.params.iter().rev().find(|(k, _)| k == key).map(|(_, v)| v.as_str())
    }

    /// A numeric parameter, with a clear error when it is not a whole number or is past
    /// the largest value the setting holds.
    pub fn param_num<T: UrlNumber>(&self, key: &str) -> Result<Option<T>> {
        let Some(v) = self.param(key) else { return Ok(None) };
        if let Ok(n) = v.parse() {
            return Ok(Some(n));
        }
        let digits = !v.is_empty() && v.bytes().all(|b| b.is_ascii_digit());
        let param = format!("{key}={v}");
        Err(Error::usage(if digits {
            crate::msg!("url-param-too-large", param = param, url = self.text.as_str(), max = T::MAX.to_string())
        } else {
            crate::msg!("url-param-not-number", param = param, url = self.text.as_str())
        }))
    }

    /// This URL without parameter `key` (the text too): a parameter the session takes for
    /// itself before a family's driver sees the rest.
    pub fn without(mut self, key: &str) -> DeviceUrl {
        if !self.params.iter().any(|(k, _)| k == key) {
            return self;
        }
        self.params.retain(|(k, _)| k != key);
        if let Some((head, query)) = self.text.split_once('?') {
            let kept: Vec<&str> = query
                .split('&')
                .filter(|p| !p.is_empty() && !p.split('=').next().unwrap_or("").eq_ignore_ascii_case(key))
                .collect();
            self.text = if kept.is_empty() { head.to_string() } else { format!("{head}?{}", kept.join("&")) };
        }
        self
    }

    /// Errors on parameters outside `known`, so typos do not pass silently.
    pub fn expect_params(&self, known: &[&str]) -> Result<()> {
        for (k, _) in &self.params {
            if !known.contains(&k.as_str()) {
                return Err(Error::usage(crate::msg!("url-unknown-param", key = k.as_str(), url = self.text.as_str()))
                    .hint(crate::msg!("url-known-params-hint", list = known.join(", "))));
            }
        }
        Ok(())
    }
}

/// The unsigned types a URL parameter is read into, with their largest value for messages.
pub trait UrlNumber: std::str::FromStr {
    const MAX: u64;
}

impl UrlNumber for u8 {
    const MAX: u64 = u8::MAX as u64;
}
impl UrlNumber for u16 {
    const MAX: u64 = u16::MAX as u64;
}
impl UrlNumber for u32 {
    const MAX: u64 = u32::MAX as u64;
}
impl UrlNumber for u64 {
    const MAX: u64 = u64::MAX;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_parameter_can_be_taken_out() {
        let u = DeviceUrl::parse("tcp://127.0.0.1:5020?unit=2&control=/tmp/k2.ctl").unwrap().without("control");
        assert_eq!((u.text.as_str(), u.params.len()), ("tcp://127.0.0.1:5020?unit=2", 1));
        let u = DeviceUrl::parse("fx:/dev/ttyUSB0?CONTROL=/x").unwrap().without("control");
        assert_eq!((u.text.as_str(), u.params.is_empty()), ("fx:/dev/ttyUSB0", true));
    }

    #[test]
    fn splits_scheme_target_and_params() {
        let u = DeviceUrl::parse("tcp://127.0.0.1:502?unit=3&model=K204ET-16DT").unwrap();
        assert_eq!(u.scheme, "tcp");
        assert_eq!(u.target, "127.0.0.1:502");
        assert_eq!(u.param("unit"), Some("3"));
        assert_eq!(u.param_num::<u8>("unit").unwrap(), Some(3));
        let s = DeviceUrl::parse("sim:K209M-56DT").unwrap();
        assert_eq!((s.scheme.as_str(), s.target.as_str()), ("sim", "K209M-56DT"));
        let r = DeviceUrl::parse("rtu:/dev/ttyUSB0?baud=115200").unwrap();
        assert_eq!(r.target, "/dev/ttyUSB0");
        assert!(DeviceUrl::parse("nothing").is_err());
        assert!(u.expect_params(&["unit"]).is_err());
        assert!(DeviceUrl::parse("x:?unit=a").unwrap().param_num::<u8>("unit").is_err());
    }

    #[test]
    fn a_number_too_large_names_the_limit() {
        let u = DeviceUrl::parse("x:?unit=300&baud=99999999999&retries=-1").unwrap();
        let e = u.param_num::<u8>("unit").unwrap_err();
        assert!(e.message.contains("`unit=300`") && e.message.contains("255"), "{e}");
        let e = u.param_num::<u32>("baud").unwrap_err();
        assert!(e.message.contains("4294967295"), "{e}");
        let e = u.param_num::<u32>("retries").unwrap_err();
        assert!(e.message.contains("not a whole number"), "{e}");
    }
}
