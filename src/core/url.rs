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
            return Err(Error::usage(format!("`{t}` is not a device URL")).hint(
                "use sim:MODEL, tcp://HOST:PORT?unit=1, rtu:/dev/ttyUSB0?baud=115200, rtu+tcp://HOST:PORT, kinco:/dev/ttyUSB0?id=1 or sim-servo:?id=1",
            ));
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

    /// A numeric parameter, with a clear error when it is not a number.
    pub fn param_num<T: std::str::FromStr>(&self, key: &str) -> Result<Option<T>> {
        match self.param(key) {
            None => Ok(None),
            Some(v) => {
                v.parse().map(Some).map_err(|_| Error::usage(format!("`{key}={v}` in {} is not a number", self.text)))
            }
        }
    }

    /// Errors on parameters outside `known`, so typos do not pass silently.
    pub fn expect_params(&self, known: &[&str]) -> Result<()> {
        for (k, _) in &self.params {
            if !known.contains(&k.as_str()) {
                return Err(Error::usage(format!("unknown parameter `{k}` in {}", self.text))
                    .hint(format!("known: {}", known.join(", "))));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
}
