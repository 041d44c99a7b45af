//! Line charts of named series (time, value): in the terminal with Unicode braille (2×4 dots
//! per character) and as an SVG picture. Pure: series in, text out, no I/O.
//!
//! Used by `plot` (the last `trace`) and meant for anything else with a value over time — a
//! PTO profile plan (frequency over time, drawn before it is sent) is a [`Series`] with
//! `steps: true` when each segment holds its frequency, or `false` for a linear ramp:
//!
//! ```
//! use plcsh::plot::{terminal, svg, Series};
//! let plan = Series::new("PTO0 frequency", "Hz", vec![(0.0, 0.0), (0.5, 1000.0), (1.5, 1000.0), (2.0, 0.0)]);
//! let text = terminal(&[plan.clone()], 60, 8);   // print it
//! let picture = svg(&[plan], 800, 200);          // write it to a file
//! assert!(text.contains("PTO0 frequency") && picture.starts_with("<svg"));
//! ```
//!
//! Hand-written rather than a crate: the charts are ~200 lines, the same series model feeds
//! both the terminal and the SVG, and the output is plain text we can test exactly.

use std::fmt::Write;

/// A named series of (time in seconds, value) points, in time order.
#[derive(Clone, Debug, PartialEq)]
pub struct Series {
    pub name: String,
    /// Unit of the values (`Hz`, `rpm`, or empty).
    pub unit: String,
    pub points: Vec<(f64, f64)>,
    /// Draw as steps (a value holds until the next point) instead of straight lines.
    pub steps: bool,
}

impl Series {
    pub fn new(name: impl Into<String>, unit: impl Into<String>, points: Vec<(f64, f64)>) -> Series {
        Series { name: name.into(), unit: unit.into(), points, steps: false }
    }

    /// The same series drawn as steps.
    pub fn stepped(mut self) -> Series {
        self.steps = true;
        self
    }

    fn range(&self) -> ((f64, f64), (f64, f64)) {
        let (mut t0, mut t1, mut v0, mut v1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for &(t, v) in self.points.iter().filter(|(t, v)| t.is_finite() && v.is_finite()) {
            t0 = t0.min(t);
            t1 = t1.max(t);
            v0 = v0.min(v);
            v1 = v1.max(v);
        }
        if t0 > t1 {
            return ((0.0, 1.0), (0.0, 1.0));
        }
        if t1 == t0 {
            t1 = t0 + 1.0;
        }
        if v1 == v0 {
            v0 -= 1.0;
            v1 += 1.0;
        }
        ((t0, t1), (v0, v1))
    }
}

/// A number as a label: integers without decimals, others with up to 3.
pub fn number(v: f64) -> String {
    if v == v.trunc() && v.abs() < 1e15 {
        format!("{}", v as i64)
    } else {
        let s = format!("{v:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    }
}

/// A time in seconds as a label (`0s`, `1.5s`, `250ms`).
pub fn time(t: f64) -> String {
    if t != 0.0 && t.abs() < 1.0 {
        format!("{}ms", number(t * 1000.0))
    } else {
        format!("{}s", number(t))
    }
}

/// A braille dot canvas.
struct Canvas {
    w: usize,
    h: usize,
    cells: Vec<u8>,
}

impl Canvas {
    fn new(cols: usize, rows: usize) -> Canvas {
        Canvas { w: cols * 2, h: rows * 4, cells: vec![0; cols * rows] }
    }

    fn set(&mut self, x: i64, y: i64) {
        if x < 0 || y < 0 || x as usize >= self.w || y as usize >= self.h {
            return;
        }
        let (x, y) = (x as usize, y as usize);
        // Braille dot numbering: left column 1,2,3,7; right column 4,5,6,8.
        const BITS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
        self.cells[(y / 4) * (self.w / 2) + x / 2] |= BITS[x % 2][y % 4];
    }

    fn line(&mut self, (x0, y0): (i64, i64), (x1, y1): (i64, i64)) {
        let (dx, dy) = ((x1 - x0).abs(), -(y1 - y0).abs());
        let (sx, sy) = (if x0 < x1 { 1 } else { -1 }, if y0 < y1 { 1 } else { -1 });
        let (mut x, mut y, mut err) = (x0, y0, dx + dy);
        loop {
            self.set(x, y);
            if x == x1 && y == y1 {
                break;
            }
            let e2 = 2 * err;
            if e2 >= dy {
                err += dy;
                x += sx;
            }
            if e2 <= dx {
                err += dx;
                y += sy;
            }
        }
    }

    fn row(&self, r: usize) -> String {
        let cols = self.w / 2;
        self.cells[r * cols..(r + 1) * cols].iter().map(|b| char::from_u32(0x2800 + *b as u32).unwrap_or(' ')).collect()
    }
}

/// One chart per series, `width` × `height` characters of plot area each, time on the x axis.
pub fn terminal(series: &[Series], width: usize, height: usize) -> String {
    let (width, height) = (width.max(8), height.max(2));
    let mut out = String::new();
    for s in series {
        let ((t0, t1), (v0, v1)) = s.range();
        let mut c = Canvas::new(width, height);
        let px = |t: f64| ((t - t0) / (t1 - t0) * (c.w - 1) as f64).round() as i64;
        let py = |v: f64| ((v1 - v) / (v1 - v0) * (c.h - 1) as f64).round() as i64;
        let pts: Vec<(i64, i64)> =
            s.points.iter().filter(|(t, v)| t.is_finite() && v.is_finite()).map(|&(t, v)| (px(t), py(v))).collect();
        for pair in pts.windows(2) {
            if s.steps {
                let corner = (pair[1].0, pair[0].1);
                c.line(pair[0], corner);
                c.line(corner, pair[1]);
            } else {
                c.line(pair[0], pair[1]);
            }
        }
        if let [only] = pts.as_slice() {
            c.set(only.0, only.1);
        }
        let unit = if s.unit.is_empty() { String::new() } else { format!(" ({})", s.unit) };
        let _ = writeln!(out, "{}{unit}", s.name);
        let (top, bottom) = (number(v1), number(v0));
        let lw = top.len().max(bottom.len());
        for r in 0..height {
            let label = match r {
                0 => format!("{top:>lw$} ┤"),
                r if r == height - 1 => format!("{bottom:>lw$} ┤"),
                _ => format!("{:>lw$} │", ""),
            };
            let _ = writeln!(out, "{label}{}", c.row(r));
        }
        let _ = writeln!(out, "{:>lw$} └{}", "", "─".repeat(width));
        let (l, r) = (time(t0), time(t1));
        let gap = (width + 1).saturating_sub(l.len() + r.len()).max(1);
        let _ = writeln!(out, "{:>lw$}  {l}{}{r}", "", " ".repeat(gap));
    }
    out
}

fn xml(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// An SVG picture: one panel per series, stacked, each `panel_height` pixels high.
pub fn svg(series: &[Series], width: u32, panel_height: u32) -> String {
    let (w, ph) = (width.max(200) as f64, panel_height.max(80) as f64);
    let (left, right, top, bottom) = (70.0, 20.0, 24.0, 28.0);
    let total = ph * series.len().max(1) as f64;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{total}" viewBox="0 0 {w} {total}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(out, r#"<rect width="{w}" height="{total}" fill="white"/>"#);
    for (i, s) in series.iter().enumerate() {
        let y0 = i as f64 * ph;
        let ((t0, t1), (v0, v1)) = s.range();
        let (pw, plot_h) = (w - left - right, ph - top - bottom);
        let x = |t: f64| left + (t - t0) / (t1 - t0) * pw;
        let y = |v: f64| y0 + top + (v1 - v) / (v1 - v0) * plot_h;
        let unit = if s.unit.is_empty() { String::new() } else { format!(" ({})", s.unit) };
        let _ = writeln!(
            out,
            r#"<text x="{left}" y="{}" font-weight="bold">{}{}</text>"#,
            y0 + 16.0,
            xml(&s.name),
            xml(&unit)
        );
        let _ = writeln!(
            out,
            r##"<path d="M{left} {} V{} H{}" fill="none" stroke="#888"/>"##,
            y0 + top,
            y0 + top + plot_h,
            left + pw
        );
        for (v, anchor_y) in [(v1, y0 + top + 4.0), (v0, y0 + top + plot_h)] {
            let _ = writeln!(out, r#"<text x="{}" y="{anchor_y}" text-anchor="end">{}</text>"#, left - 6.0, number(v));
        }
        for (t, anchor) in [(t0, "start"), (t1, "end")] {
            let _ =
                writeln!(out, r#"<text x="{}" y="{}" text-anchor="{anchor}">{}</text>"#, x(t), y0 + ph - 8.0, time(t));
        }
        let mut d = String::new();
        let mut prev: Option<(f64, f64)> = None;
        for &(t, v) in s.points.iter().filter(|(t, v)| t.is_finite() && v.is_finite()) {
            let (px, py) = (x(t), y(v));
            match prev {
                None => {
                    let _ = write!(d, "M{px:.1} {py:.1}");
                }
                Some((_, last_y)) if s.steps => {
                    let _ = write!(d, " L{px:.1} {last_y:.1} L{px:.1} {py:.1}");
                }
                Some(_) => {
                    let _ = write!(d, " L{px:.1} {py:.1}");
                }
            }
            prev = Some((px, py));
        }
        let _ = writeln!(out, r##"<path d="{d}" fill="none" stroke="#1f77b4" stroke-width="1.5"/>"##);
    }
    out.push_str("</svg>\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rising_line_goes_from_bottom_left_to_top_right() {
        let s = Series::new("ramp", "Hz", vec![(0.0, 0.0), (2.0, 100.0)]);
        let text = terminal(&[s], 10, 3);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "ramp (Hz)");
        assert!(lines[1].starts_with("100 ┤"), "{text}");
        assert!(lines[3].starts_with("  0 ┤"), "{text}");
        let plot = |l: &str| l.chars().skip(5).collect::<Vec<char>>();
        // Bottom-left and top-right cells carry dots; top-left and bottom-right are empty.
        assert_ne!(plot(lines[3])[0], '\u{2800}');
        assert_eq!(plot(lines[3])[9], '\u{2800}');
        assert_eq!(plot(lines[1])[0], '\u{2800}');
        assert_ne!(plot(lines[1])[9], '\u{2800}');
        assert_eq!(lines[4], "    └──────────");
        assert!(lines[5].trim_start().starts_with("0s") && lines[5].ends_with("2s"), "{text}");
    }

    #[test]
    fn braille_dots_follow_the_unicode_numbering() {
        let mut c = Canvas::new(1, 1);
        c.set(0, 0);
        c.set(1, 3);
        assert_eq!(c.row(0), "\u{2881}");
    }

    #[test]
    fn steps_hold_the_value_until_the_next_point() {
        let s = Series::new("f", "", vec![(0.0, 1.0), (1.0, 0.0)]).stepped();
        let lines: Vec<String> = terminal(&[s], 4, 2).lines().map(String::from).collect();
        // The top row is lit across (the held value), the bottom row only at the end.
        let top: Vec<char> = lines[1].chars().skip(4).collect();
        assert!(top.iter().all(|c| *c != '\u{2800}'), "{lines:?}");
        let bottom: Vec<char> = lines[2].chars().skip(4).collect();
        assert_eq!(bottom[0], '\u{2800}');
    }

    #[test]
    fn svg_has_a_panel_per_series_and_escapes_names() {
        let a = Series::new("VW0", "", vec![(0.0, 1.0), (0.5, 3.0)]);
        let b = Series::new("a<b", "", vec![(0.0, 0.0), (0.5, 1.0)]).stepped();
        let s = svg(&[a, b], 400, 150);
        assert!(s.starts_with("<svg") && s.trim_end().ends_with("</svg>"));
        assert!(s.contains(r#"height="300""#));
        assert!(s.contains("a&lt;b") && !s.contains("a<b"));
        assert_eq!(s.matches("stroke=\"#1f77b4\"").count(), 2);
        // 400 wide: plot x 70…380; 150 high: plot y 24…122 (margins 24 top, 28 bottom).
        assert!(s.contains("M70.0 122.0 L380.0 24.0"), "{s}");
    }

    #[test]
    fn labels() {
        assert_eq!(number(1000.0), "1000");
        assert_eq!(number(0.25), "0.25");
        assert_eq!(time(0.25), "250ms");
        assert_eq!(time(2.0), "2s");
        assert_eq!(time(0.0), "0s");
    }

    #[test]
    fn flat_and_empty_series_do_not_divide_by_zero() {
        let flat = Series::new("x", "", vec![(0.0, 5.0), (1.0, 5.0)]);
        assert!(terminal(&[flat], 10, 3).contains("6 ┤"));
        assert!(terminal(&[Series::new("e", "", vec![])], 10, 3).contains('e'));
    }
}
