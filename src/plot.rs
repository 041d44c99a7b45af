//! Line charts of named series (time, value): in the terminal with Unicode braille (2×4 dots
//! per character), and as SVG or PNG pictures drawn with `plotters` (axes, ticks, grid, axis
//! names with units, a title and a legend) for reports.
//!
//! Used by `plot` (the last `trace`) and meant for anything else with a value over time — a
//! PTO profile plan (frequency over time, drawn before it is sent) is a [`Series`] with
//! `steps: true` when each segment holds its frequency, or `false` for a linear ramp:
//!
//! ```
//! use plcsh::plot::{terminal, svg, Series};
//! let plan = Series::new("PTO0 frequency", "Hz", vec![(0.0, 0.0), (0.5, 1000.0), (1.5, 1000.0), (2.0, 0.0)]);
//! let text = terminal(&[plan.clone()], 60, 8);   // print it
//! let picture = svg(&[plan], "PTO0 plan", 800, 300).unwrap();   // or png(…, path)
//! assert!(text.contains("PTO0 frequency") && picture.starts_with("<svg"));
//! ```
//!
//! The terminal chart is hand-written (plain text we can test exactly); pictures use plotters,
//! a maintained plotting library, with its pure-Rust bitmap and SVG backends and a built-in
//! font, so no system library is needed.

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

    /// The data's extent, without adjustments (`(inf, -inf)` when empty).
    fn range_raw(&self) -> ((f64, f64), (f64, f64)) {
        let (mut t0, mut t1, mut v0, mut v1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
        for &(t, v) in self.points.iter().filter(|(t, v)| t.is_finite() && v.is_finite()) {
            t0 = t0.min(t);
            t1 = t1.max(t);
            v0 = v0.min(v);
            v1 = v1.max(v);
        }
        ((t0, t1), (v0, v1))
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

/// DejaVu Sans (Bitstream Vera license, `assets/fonts/DejaVuSans-LICENSE.txt`), built in so
/// pictures render the same everywhere without fontconfig or a system font.
static FONT: &[u8] = include_bytes!("../assets/fonts/DejaVuSans.ttf");
const FAMILY: &str = "sans-serif";
/// Line colours (matplotlib's first four, legible on white and in greyscale print).
const COLORS: [plotters::style::RGBColor; 4] = [
    plotters::style::RGBColor(31, 119, 180),
    plotters::style::RGBColor(214, 39, 40),
    plotters::style::RGBColor(44, 160, 44),
    plotters::style::RGBColor(255, 127, 14),
];

fn register_font() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        let _ = plotters::style::register_font(FAMILY, plotters::style::FontStyle::Normal, FONT);
    });
}

/// Series with the same unit share a panel (the legend tells them apart); each unit gets its own.
fn panels(series: &[Series]) -> Vec<Vec<&Series>> {
    let mut out: Vec<Vec<&Series>> = Vec::new();
    for s in series {
        match out.iter_mut().find(|g| g[0].unit == s.unit && !s.unit.is_empty()) {
            Some(g) => g.push(s),
            None => out.push(vec![s]),
        }
    }
    out
}

/// The axis range of a panel: a little headroom, a BOOL as 0…1, a flat line in the middle.
fn panel_range(group: &[&Series]) -> ((f64, f64), (f64, f64)) {
    let (mut t0, mut t1, mut v0, mut v1) = (f64::INFINITY, f64::NEG_INFINITY, f64::INFINITY, f64::NEG_INFINITY);
    for s in group {
        let ((a, b), (c, d)) = s.range_raw();
        t0 = t0.min(a);
        t1 = t1.max(b);
        v0 = v0.min(c);
        v1 = v1.max(d);
    }
    if t0 > t1 {
        return ((0.0, 1.0), (0.0, 1.0));
    }
    if t1 == t0 {
        t1 = t0 + 1.0;
    }
    if v0 >= 0.0 && v1 <= 1.0 && group.iter().all(|s| s.points.iter().all(|p| p.1 == 0.0 || p.1 == 1.0)) {
        return ((t0, t1), (-0.1, 1.1));
    }
    if v1 == v0 {
        let pad = if v0 == 0.0 { 1.0 } else { v0.abs() * 0.1 };
        return ((t0, t1), (v0 - pad, v1 + pad));
    }
    let pad = (v1 - v0) * 0.06;
    // Frequencies are read against zero; other non-negative data keeps its axis above zero.
    let from_zero = v0 >= 0.0 && group.iter().all(|s| s.unit == "Hz");
    let lo = if from_zero || (v0 >= 0.0 && v0 - pad < 0.0) { 0.0 } else { v0 - pad };
    ((t0, t1), (lo, v1 + pad))
}

/// The drawn points: steps become horizontal-then-vertical pairs. A series of only 0 and 1 (a
/// bit) is drawn as steps too: a bit holds its level until the next sample.
fn polyline(s: &Series) -> Vec<(f64, f64)> {
    let pts: Vec<(f64, f64)> = s.points.iter().copied().filter(|(t, v)| t.is_finite() && v.is_finite()).collect();
    let bit = pts.iter().all(|p| p.1 == 0.0 || p.1 == 1.0);
    if !s.steps && !bit {
        return pts;
    }
    let mut out = Vec::with_capacity(pts.len() * 2);
    for (k, p) in pts.iter().enumerate() {
        if k > 0 {
            out.push((p.0, pts[k - 1].1));
        }
        out.push(*p);
    }
    out
}

/// Draws the chart on any plotters backend: a title, then one panel per unit with axes,
/// ticks, a grid, axis names with units and a legend.
fn draw<DB: plotters::prelude::DrawingBackend>(
    root: plotters::drawing::DrawingArea<DB, plotters::coord::Shift>,
    series: &[Series],
    title: &str,
) -> Result<(), String> {
    use plotters::prelude::*;
    register_font();
    let e = |e: plotters::drawing::DrawingAreaErrorKind<DB::ErrorType>| {
        crate::msg!("plot-cannot-draw", error = e.to_string()).text
    };
    root.fill(&WHITE).map_err(e)?;
    let root = root.titled(title, (FAMILY, 22)).map_err(e)?;
    let groups = panels(series);
    let areas = root.split_evenly((groups.len().max(1), 1));
    for (area, group) in areas.iter().zip(&groups) {
        let ((t0, t1), (v0, v1)) = panel_range(group);
        let unit = &group[0].unit;
        let caption = group.iter().map(|s| s.name.as_str()).collect::<Vec<_>>().join(", ");
        let mut chart = ChartBuilder::on(area)
            .caption(caption, (FAMILY, 16))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(t0..t1, v0..v1)
            .map_err(e)?;
        let y_desc = if unit.is_empty() { "value".to_string() } else { unit.clone() };
        let is_bool = v0 == -0.1 && v1 == 1.1;
        chart
            .configure_mesh()
            .x_desc("time (s)")
            .y_desc(y_desc)
            .x_label_formatter(&|x| number(*x))
            .y_label_formatter(&|y| number(*y))
            .y_labels(if is_bool { 3 } else { 8 })
            .light_line_style(RGBColor(235, 235, 235))
            .bold_line_style(RGBColor(200, 200, 200))
            .label_style((FAMILY, 13))
            .axis_desc_style((FAMILY, 14))
            .draw()
            .map_err(e)?;
        for (i, s) in group.iter().enumerate() {
            let color = COLORS[i % COLORS.len()];
            let label = if s.unit.is_empty() { s.name.clone() } else { format!("{} ({})", s.name, s.unit) };
            chart
                .draw_series(LineSeries::new(polyline(s), color.stroke_width(2)))
                .map_err(e)?
                .label(label)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2)));
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(RGBColor(160, 160, 160))
            .label_font((FAMILY, 13))
            .draw()
            .map_err(e)?;
    }
    root.present().map_err(e)
}

/// An SVG picture of the series, `width` × `height` pixels.
pub fn svg(series: &[Series], title: &str, width: u32, height: u32) -> Result<String, String> {
    let mut buf = String::new();
    {
        use plotters::prelude::IntoDrawingArea;
        let root = plotters::prelude::SVGBackend::with_string(&mut buf, (width, height)).into_drawing_area();
        draw(root, series, title)?;
    }
    Ok(buf)
}

/// A PNG picture of the series, `width` × `height` pixels, written to `path`.
pub fn png(series: &[Series], title: &str, width: u32, height: u32, path: &std::path::Path) -> Result<(), String> {
    use plotters::prelude::IntoDrawingArea;
    let root = plotters::prelude::BitMapBackend::new(path, (width, height)).into_drawing_area();
    draw(root, series, title)
}

/// Smallest and largest picture side, in pixels.
pub const PICTURE_SIDES: std::ops::RangeInclusive<u32> = 100..=8000;

/// Writes the picture `path` names: `.png` or `.svg`, anything else is refused.
pub fn write_picture(path: &str, series: &[Series], title: &str, (w, h): (u32, u32)) -> crate::core::Result<()> {
    use crate::core::Error;
    let lower = path.to_ascii_lowercase();
    let r = if lower.ends_with(".png") {
        png(series, title, w, h, std::path::Path::new(path))
    } else if lower.ends_with(".svg") {
        svg(series, title, w, h).and_then(|text| std::fs::write(path, text).map_err(|e| e.to_string()))
    } else {
        return Err(Error::usage(crate::msg!("plot-bad-picture", path = path)).hint(crate::msg!("plot-hint-picture")));
    };
    r.map_err(|m| Error::io(crate::msg!("plot-cannot-write", path = path, error = m)))
}

/// The default picture size: 900 wide, 300 per panel.
pub fn default_size(series: &[Series]) -> (u32, u32) {
    (900, 60 + 280 * panels(series).len().max(1) as u32)
}

/// `size=900x400` → (900, 400).
pub fn parse_size(text: &str) -> std::result::Result<(u32, u32), String> {
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(|| crate::msg!("plot-bad-size", text = text).text)?;
    let n = |s: &str| s.trim().parse::<u32>().ok().filter(|n| PICTURE_SIDES.contains(n));
    match (n(w), n(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => {
            Err(crate::msg!("plot-size-range", text = text, min = *PICTURE_SIDES.start(), max = *PICTURE_SIDES.end())
                .text)
        }
    }
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
    fn svg_has_axes_a_title_a_legend_and_a_panel_per_unit() {
        let a = Series::new("VW0", "rpm", vec![(0.0, 1.0), (0.5, 3.0)]);
        let b = Series::new("a<b", "", vec![(0.0, 0.0), (0.5, 1.0)]).stepped();
        let s = svg(&[a, b], "trace", 600, 500).unwrap();
        assert!(s.starts_with("<svg") && s.trim_end().ends_with("</svg>"));
        assert!(s.contains(r#"width="600""#) && s.contains(r#"height="500""#));
        assert!(s.contains("a&lt;b") && !s.contains("\na<b\n"), "names are escaped");
        assert_eq!(s.matches("\ntime (s)\n").count(), 2, "an x axis name per panel");
        assert!(s.contains("\nrpm\n") && s.contains("\nVW0 (rpm)\n") && s.contains("\ntrace\n"), "{s}");
    }

    #[test]
    fn pngs_have_the_requested_size() {
        let dir = std::env::temp_dir().join(format!("plcsh-plot-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("p.png");
        let s = Series::new("PTO0 frequency", "Hz", vec![(0.0, 0.0), (1.0, 1000.0), (2.0, 1000.0)]).stepped();
        png(&[s], "plan", 640, 360, &path).unwrap();
        let bytes = std::fs::read(&path).unwrap();
        assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
        assert_eq!(u32::from_be_bytes(bytes[16..20].try_into().unwrap()), 640);
        assert_eq!(u32::from_be_bytes(bytes[20..24].try_into().unwrap()), 360);
        assert!(write_picture(dir.join("p.jpg").to_str().unwrap(), &[], "x", (200, 200)).is_err());
        assert_eq!(parse_size("900x400"), Ok((900, 400)));
        assert!(parse_size("9x4").is_err());
    }

    #[test]
    fn a_bool_gets_a_0_to_1_axis_and_a_flat_line_a_centred_one() {
        let b = Series::new("Q0.0", "", vec![(0.0, 1.0), (1.0, 1.0)]);
        assert_eq!(panel_range(&[&b]).1, (-0.1, 1.1));
        let f = Series::new("VW0", "", vec![(0.0, 50.0), (1.0, 50.0)]);
        assert_eq!(panel_range(&[&f]).1, (45.0, 55.0));
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
