//! `crop` and `pad`: window changes. `crop --region` sets the data window
//! to a region, cutting or padding with black (oiiotool's `--crop`), and
//! with `--display` the display window too (Nuke's Crop, reformatted);
//! `--cut` moves the region to the origin, data and display window both
//! (oiiotool's `--cut`). `pad` grows the data window (overscan), and with
//! `--display` the display window, by a number of pixels on each side.
//! A crop or pad copies rows in the output's columns (no region of its
//! own); a cut reads its input shifted (`Op::request`). Rules:
//! specs/ops.md, "crop, pad".

use super::declare::{input, params, Args, Length, Operation, Value};
use crate::engine::graph::{intersection, moved, Carried, Display, GraphBuilder, NodeId, Op};
use crate::io::rows::{Rows, RowsMut};
use exr::meta::attribute::{ChannelDescription, IntegerBounds};
use std::sync::OnceLock;

pub const CROP: Operation = Operation {
    name: "crop",
    about: "Set the data window to a region, cutting or padding with black (oiiotool's --crop); \
            --display sets the display window too, --cut moves the region to the origin \
            (oiiotool's --cut)",
    inputs: &[input("input", "Input file or sequence, `:PART` for a part")],
    repeats: false,
    params: CropParams::PARAMS,
    layers: false,
    straight: false,
    header: Some(0),
    build: build_crop,
    measure: None,
};

pub const PAD: Operation = Operation {
    name: "pad",
    about: "Grow the data window by black pixels on each side (overscan); --display grows the \
            display window too",
    params: PadParams::PARAMS,
    build: build_pad,
    ..CROP
};

params! {
    pub struct CropParams {
        /// The region in pixels: WxH+X+Y, or X0,Y0,X1,Y1 with X1 and Y1 included (oiiotool's geometry).
        region: Region {pixels},
        /// The display window becomes the region too.
        display: bool,
        /// Move the region to the origin; data and display window both become it (oiiotool's --cut).
        cut: bool,
    }
}

params! {
    pub struct PadParams {
        /// Pixels added on each side: N, or LEFT,TOP,RIGHT,BOTTOM.
        by: Sides {pixels},
        /// The display window grows too.
        display: bool,
    }
}

fn build_crop(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = CropParams::read(args)?;
    let op = Crop {
        window: Window::Region(p.region.0),
        display: p.display || p.cut,
        cut: p.cut,
        placed: OnceLock::new(),
    };
    Ok(graph.add(op, inputs))
}

fn build_pad(args: &Args, graph: &mut GraphBuilder, inputs: &[NodeId]) -> Result<NodeId, String> {
    let p = PadParams::read(args)?;
    let op = Crop {
        window: Window::Grow(p.by),
        display: p.display,
        cut: false,
        placed: OnceLock::new(),
    };
    Ok(graph.add(op, inputs))
}

/// A rectangle as oiiotool writes one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Region(pub IntegerBounds);

impl Value for Region {
    fn parse(text: &str) -> Result<Self, String> {
        let bad = || {
            format!(
                "region '{text}': expected WxH+X+Y (1920x1080+0+0) or X0,Y0,X1,Y1 \
                 (0,0,1919,1079), a size of 1 to 1048576 pixels a side"
            )
        };
        let number = |s: &str| s.trim().parse::<i32>().ok().filter(|v| v.abs() <= 1 << 24);
        let (x0, y0, w, h) = if let Some((w, rest)) = text.split_once(['x', 'X']) {
            // WxH, then +X+Y or -X-Y (signs kept).
            let at = rest.find(['+', '-']).ok_or_else(bad)?;
            let (h, offsets) = rest.split_at(at);
            let split = offsets[1..].find(['+', '-']).ok_or_else(bad)? + 1;
            let (x, y) = offsets.split_at(split);
            let (x, y) = (number(x).ok_or_else(bad)?, number(y).ok_or_else(bad)?);
            (x, y, number(w).ok_or_else(bad)?, number(h).ok_or_else(bad)?)
        } else {
            let v: Vec<i32> = text
                .split(',')
                .map(number)
                .collect::<Option<_>>()
                .ok_or_else(bad)?;
            let [x0, y0, x1, y1] = v[..] else {
                return Err(bad());
            };
            (x0, y0, x1 - x0 + 1, y1 - y0 + 1)
        };
        if !(1..=1 << 20).contains(&w) || !(1..=1 << 20).contains(&h) {
            return Err(bad());
        }
        Ok(Region(IntegerBounds::new(
            (x0, y0),
            (w as usize, h as usize),
        )))
    }
}

/// The whole pixels covering the region scaled (its start floored, its end
/// ceiled, as a resize maps a data window), as X0,Y0,X1,Y1.
impl Length for Region {
    fn scaled(text: &str, factor: f64) -> Result<String, String> {
        let Region(r) = Region::parse(text)?;
        let low = |v: i32| (v as f64 * factor).floor() as i64;
        let high = |v: i32| (v as f64 * factor).ceil() as i64 - 1;
        Ok(format!(
            "{},{},{},{}",
            low(r.position.x()),
            low(r.position.y()),
            high(r.end().x()),
            high(r.end().y())
        ))
    }
}

/// Pixels to add on each side: left, top, right, bottom.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sides([i32; 4]);

impl Value for Sides {
    fn parse(text: &str) -> Result<Self, String> {
        let bad =
            || format!("'{text}': expected N or LEFT,TOP,RIGHT,BOTTOM, 0 to 65536 pixels each");
        let v: Vec<i32> = text
            .split(',')
            .map(|s| {
                s.trim()
                    .parse::<i32>()
                    .ok()
                    .filter(|v| (0..=1 << 16).contains(v))
            })
            .collect::<Option<_>>()
            .ok_or_else(bad)?;
        match v[..] {
            [n] => Ok(Sides([n; 4])),
            [l, t, r, b] => Ok(Sides([l, t, r, b])),
            _ => Err(bad()),
        }
    }
}

/// Each side scaled and rounded.
impl Length for Sides {
    fn scaled(text: &str, factor: f64) -> Result<String, String> {
        let Sides(sides) = Sides::parse(text)?;
        let side = |v: i32| (v as f64 * factor).round() as i64;
        Ok(format!(
            "{},{},{},{}",
            side(sides[0]),
            side(sides[1]),
            side(sides[2]),
            side(sides[3])
        ))
    }
}

#[derive(Debug)]
enum Window {
    Region(IntegerBounds),
    Grow(Sides),
    /// The image placed in a format (`reformat`): at its top left corner,
    /// or centred.
    Place(IntegerBounds, bool),
}

impl Window {
    /// The new window, from the one it changes.
    fn of(&self, old: IntegerBounds) -> IntegerBounds {
        match self {
            Window::Region(region) | Window::Place(region, _) => *region,
            Window::Grow(Sides([l, t, r, b])) => IntegerBounds::new(
                (old.position.x() - l, old.position.y() - t),
                (
                    old.size.width() + (l + r) as usize,
                    old.size.height() + (t + b) as usize,
                ),
            ),
        }
    }
}

#[derive(Debug)]
pub struct Crop {
    window: Window,
    display: bool,
    /// Moved: to the origin (a cut), or into a format.
    cut: bool,
    /// A placed image's shift, from the first frame (`reformat`'s size
    /// follows its input's, which a sequence keeps).
    placed: OnceLock<(i32, i32)>,
}

impl Crop {
    /// A format's display window with `input` placed in it (`reformat`).
    pub fn place(format: IntegerBounds, center: bool) -> Self {
        Crop {
            window: Window::Place(format, center),
            display: true,
            cut: true,
            placed: OnceLock::new(),
        }
    }

    /// How far the output is moved from the input (output pixel (x, y) is
    /// input pixel (x + dx, y + dy)): the region's corner for a cut, the
    /// placement for `reformat`, else nothing.
    fn shift(&self) -> (i32, i32) {
        match (&self.window, self.cut) {
            (Window::Place(..), _) => *self.placed.get().expect("the display window comes first"),
            (Window::Region(r), true) => (r.position.x(), r.position.y()),
            _ => (0, 0),
        }
    }
}

impl Op for Crop {
    fn display_window(&self, inputs: &[Display]) -> Result<Option<Display>, String> {
        let shown = |window| Display {
            window,
            pixel_aspect: inputs[0].pixel_aspect,
        };
        if let Window::Place(format, center) = self.window {
            // The image's display window's corner to the format's, or its
            // centre to the format's centre (whole pixels, as oiiotool's --fit).
            let d = inputs[0].window;
            let (ox, oy) = match center {
                true => (
                    (format.size.width() as i32 - d.size.width() as i32) / 2,
                    (format.size.height() as i32 - d.size.height() as i32) / 2,
                ),
                false => (0, 0),
            };
            let shift = (
                d.position.x() - ox - format.position.x(),
                d.position.y() - oy - format.position.y(),
            );
            if *self.placed.get_or_init(|| shift) != shift {
                return Err(
                    "reformat: the display window changed size within the sequence: \
                            reformat one size at a time"
                        .into(),
                );
            }
            return Ok(Some(shown(format)));
        }
        let (dx, dy) = self.shift();
        Ok(self
            .display
            .then(|| shown(moved(self.window.of(inputs[0].window), (-dx, -dy)))))
    }

    fn data_window(&self, inputs: &[IntegerBounds]) -> IntegerBounds {
        let (dx, dy) = self.shift();
        let window = match self.window {
            // Grown from the data window; a region as it is.
            Window::Grow(_) | Window::Place(..) if inputs[0].size.area() == 0 => {
                return IntegerBounds::zero()
            }
            Window::Place(..) => inputs[0],
            _ => self.window.of(inputs[0]),
        };
        moved(window, (-dx, -dy))
    }

    fn request(&self, out: IntegerBounds) -> Option<IntegerBounds> {
        self.cut.then(|| moved(out, self.shift()))
    }

    /// The input's pixels where it has data: in place (a crop, a pad), or
    /// moved by whole pixels (a cut, a placement).
    fn carries(&self, inputs: &[&[ChannelDescription]]) -> Option<Carried> {
        Some(Carried {
            input: 0,
            channels: (0..inputs[0].len()).collect(),
            shift: self.shift(),
        })
    }

    fn compute(&self, _frame: i64, inputs: &[&Rows], out: &mut RowsMut) -> Result<(), String> {
        let input = inputs[0];
        let (dx, dy) = self.shift();
        if !self.cut {
            // The same rows and columns, inside the crop's window only (a
            // merge it feeds computes rows and columns beyond it): black
            // outside the input's data.
            let columns = out.valid_columns();
            for y in out.valid_rows() {
                let (to, from) = (out.row_range(y).start, input.row_range(y).start);
                for (plane, source) in out.planes.iter_mut().zip(&input.planes) {
                    plane
                        .bytes_mut(to + columns.start..to + columns.end)
                        .copy_from_slice(source.bytes(from + columns.start..from + columns.end));
                }
            }
            return Ok(());
        }
        copy_moved(input, out, (dx, dy));
        Ok(())
    }
}

/// Output pixel (x, y) is input pixel (x + dx, y + dy), where both have data
/// (a merge the op feeds computes rows and columns beyond it, which stay
/// black): a cut, a placement, a resize to the same size.
pub fn copy_moved(input: &Rows, out: &mut RowsMut, (dx, dy): (i32, i32)) {
    let output = intersection(
        IntegerBounds::new((out.x, out.y), (out.width, out.height)),
        out.valid,
    );
    let have = intersection(
        moved(output, (dx, dy)),
        intersection(
            input.valid,
            IntegerBounds::new((input.x, input.y), (input.width, input.height)),
        ),
    );
    if have.size.area() == 0 {
        return;
    }
    let (x0, x1) = (have.position.x(), have.end().x());
    for y in have.position.y()..have.end().y() {
        let (to, from) = (out.row_range(y - dy).start, input.row_range(y).start);
        let (to, from) = (
            to + (x0 - dx - out.x) as usize,
            from + (x0 - input.x) as usize,
        );
        let count = (x1 - x0) as usize;
        for (plane, source) in out.planes.iter_mut().zip(&input.planes) {
            plane
                .bytes_mut(to..to + count)
                .copy_from_slice(source.bytes(from..from + count));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regions_parse_as_oiiotool_writes_them() {
        let r = |x, y, w, h| Ok(Region(IntegerBounds::new((x, y), (w, h))));
        assert_eq!(Region::parse("100x50+10+20"), r(10, 20, 100, 50));
        assert_eq!(Region::parse("100x50-10+20"), r(-10, 20, 100, 50));
        assert_eq!(Region::parse("10,20,109,69"), r(10, 20, 100, 50));
        for bad in ["100x50", "0x5+0+0", "1,2,3", "5,5,4,9", "axb+1+1"] {
            assert!(
                Region::parse(bad).unwrap_err().contains("expected WxH+X+Y"),
                "{bad}"
            );
        }
        assert_eq!(Sides::parse("8"), Ok(Sides([8; 4])));
        assert_eq!(Sides::parse("1,2,3,4"), Ok(Sides([1, 2, 3, 4])));
        assert!(Sides::parse("-1").is_err() && Sides::parse("1,2").is_err());
    }
}
