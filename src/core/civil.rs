//! Calendar dates from seconds since 1970, in one place: the K2's clock instructions, the
//! dates written into saved sets and commissioning reports. No time-zone database: plcsh
//! writes UTC (RFC 3339) and the K2's clock keeps the host's local time as plain numbers.

/// Year, month (1–12) and day (1–31) of the day `z` days after 1970-01-01 (proleptic
/// Gregorian; Howard Hinnant's `civil_from_days`).
pub fn civil_from_days(z: i64) -> (i64, u32, u32) {
    let z = z + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = (doy - (153 * mp + 2) / 5 + 1) as u32;
    let m = if mp < 10 { mp + 3 } else { mp - 9 } as u32;
    let y = yoe + era * 400 + i64::from(m <= 2);
    (y, m, d)
}

/// Seconds since 1970 as RFC 3339 UTC (`2026-12-07T21:08:13Z`).
pub fn rfc3339(s: i64) -> String {
    let (days, rem) = (s.div_euclid(86_400), s.rem_euclid(86_400));
    let (y, m, d) = civil_from_days(days);
    format!("{y:04}-{m:02}-{d:02}T{:02}:{:02}:{:02}Z", rem / 3600, rem / 60 % 60, rem % 60)
}

/// Now as RFC 3339 UTC; `SOURCE_DATE_EPOCH` (seconds, the reproducible-builds convention)
/// stands for now when set, so a rehearsal's saved sets and its commissioning report are the
/// same files every time.
pub fn utc_now() -> String {
    let s = std::env::var("SOURCE_DATE_EPOCH").ok().and_then(|v| v.trim().parse::<i64>().ok()).unwrap_or_else(|| {
        std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_secs() as i64).unwrap_or(0)
    });
    rfc3339(s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_across_leap_days_and_centuries() {
        assert_eq!(rfc3339(0), "1970-01-01T00:00:00Z");
        assert_eq!(rfc3339(951_782_400), "2000-02-29T00:00:00Z");
        assert_eq!(rfc3339(-1), "1969-12-31T23:59:59Z");
        assert_eq!(civil_from_days(-719_468), (0, 3, 1));
        assert_eq!(rfc3339(4_107_542_400), "2100-03-01T00:00:00Z", "2100 is not a leap year");
    }
}
