//! The output's header attributes as the user edits them: `--attrib
//! NAME=VALUE[:TYPE]`, `--erase-attrib NAME|GLOB`, `--fps` and `--timecode`
//! (a job's write node takes the same as keys). Values are typed as
//! oiiotool types them, attributes exrcomp writes itself are refused, and
//! OpenEXR's standard attributes keep their standard types
//! (specs/file-format.md, "Attributes set by the user").

use super::timecode::{self, Counting, TimecodeSpec};
use exr::math::Vec2;
use exr::meta::attribute::{AttributeValue, FloatRect, IntegerBounds, KeyCode, Rational, Text};
use exr::meta::header::Header;

/// The attribute recording which job made a frame (src/engine/fingerprint.rs).
pub const FINGERPRINT: &str = "exrcomp:fingerprint";

/// One `--attrib`: a name and its typed value.
#[derive(Clone, Debug, PartialEq)]
pub struct Attrib {
    pub name: String,
    pub value: AttributeValue,
}

/// The types `--attrib NAME=VALUE:TYPE` takes, as OpenEXR (and exrheader)
/// names them.
const TYPES: &[&str] = &[
    "string", "int", "float", "double", "v2i", "v2f", "v3i", "v3f", "box2i", "box2f", "m33f",
    "m44f", "rational", "timecode", "keycode",
];

/// Attributes exrcomp writes from what it writes, and why: neither set nor
/// erased by the user.
fn owned(name: &str) -> Option<&'static str> {
    Some(match name {
        "channels"
        | "compression"
        | "dataWindow"
        | "lineOrder"
        | "tiles"
        | "type"
        | "chunkCount"
        | "version"
        | "maxSamplesPerPixel"
        | "dwaCompressionLevel"
        | "deepImageState" => {
            "exrcomp writes it to describe the pixels it writes (see --compression, --tile, \
             --dwa-level)"
        }
        "displayWindow" => "the display window is the header input's: framing is not metadata",
        "name" | "view" | "multiView" => "parts and views are the inputs'",
        "preview" => "a preview's pixels would not be the output's",
        _ => return None,
    })
}

/// Attributes every OpenEXR header has: set, never erased.
fn required(name: &str) -> bool {
    matches!(
        name,
        "pixelAspectRatio" | "screenWindowCenter" | "screenWindowWidth"
    )
}

/// What exrcomp stamps on every output (specs/file-format.md, "Provenance"):
/// erased from the input's header before the stamp, never set.
fn provenance(name: &str) -> bool {
    matches!(name, "Software" | "Exif:ImageHistory")
}

/// OpenEXR's type of its standard attributes (ImfStandardAttributes.h):
/// a value given for one is of that type, so that OpenEXR reads it as the
/// attribute it is.
fn standard_type(name: &str) -> Option<&'static str> {
    Some(match name {
        "owner" | "comments" | "capDate" | "renderingTransform" | "lookModTransform"
        | "wrapmodes" => "string",
        "pixelAspectRatio" | "screenWindowWidth" | "whiteLuminance" | "xDensity" | "utcOffset"
        | "longitude" | "latitude" | "altitude" | "focus" | "expTime" | "aperture" | "isoSpeed" => {
            "float"
        }
        "screenWindowCenter" | "adoptedNeutral" => "v2f",
        "timeCode" => "timecode",
        "framesPerSecond" => "rational",
        "keyCode" => "keycode",
        "worldToCamera" | "worldToNDC" => "m44f",
        "originalDataWindow" => "box2i",
        "chromaticities" => "chromaticities",
        "envmap" => "envmap",
        _ => return None,
    })
}

/// Longest attribute name OpenEXR takes (with the long-names flag over 31).
const MAX_NAME: usize = 255;

/// `NAME=VALUE` or `NAME=VALUE:TYPE`. Without a type the value is an int if
/// it is an integer, a float if it is another number, else a string (as
/// oiiotool infers), but a standard attribute's value is of its standard
/// type. A `:SUFFIX` that is not a type name is part of the value.
pub fn parse_attrib(text: &str) -> Result<Attrib, String> {
    let Some((name, rest)) = text.split_once('=') else {
        return Err(format!(
            "'{text}': expected NAME=VALUE or NAME=VALUE:TYPE (owner=me, expTime=0.02:float)"
        ));
    };
    check_name(name)?;
    if let Some(why) = owned(name) {
        return Err(format!("'{name}' cannot be set: {why}"));
    }
    if provenance(name) {
        return Err(format!(
            "'{name}' cannot be set: exrcomp writes it (provenance); --erase-attrib \
             '{name}' drops the input's"
        ));
    }
    let (value, given) = match rest.rsplit_once(':') {
        Some((value, kind)) if TYPES.contains(&kind) => (value, Some(kind)),
        _ => (rest, None),
    };
    let kind = match (given, standard_type(name)) {
        (Some(given), Some(standard)) if given != standard => {
            return Err(format!(
                "'{name}' is OpenEXR's standard attribute of type {standard}, not {given}"
            ))
        }
        (_, Some(standard)) if !TYPES.contains(&standard) => {
            return Err(format!(
                "'{name}' has OpenEXR's type {standard}, which --attrib does not write (it \
                 can be erased)"
            ))
        }
        (given, standard) => given.or(standard).unwrap_or_else(|| infer(value)),
    };
    let value = parse_value(kind, value).map_err(|m| format!("{name}: {m}"))?;
    Ok(Attrib {
        name: name.to_string(),
        value,
    })
}

fn check_name(name: &str) -> Result<(), String> {
    if name.is_empty() || name.len() > MAX_NAME {
        return Err(format!(
            "attribute name '{name}': 1 to {MAX_NAME} bytes, as OpenEXR takes"
        ));
    }
    Ok(())
}

/// oiiotool's rule: a number with digits is an int if it has no decimal
/// point or exponent, else a float; anything else is a string.
fn infer(value: &str) -> &'static str {
    let v = value.trim();
    let numeric = v.bytes().any(|b| b.is_ascii_digit());
    match (numeric, v.parse::<i64>().is_ok(), v.parse::<f64>().is_ok()) {
        (true, true, _) => "int",
        (true, false, true) => "float",
        _ => "string",
    }
}

/// `text` as a value of OpenEXR type `kind` (one of `TYPES`).
fn parse_value(kind: &str, text: &str) -> Result<AttributeValue, String> {
    use AttributeValue as V;
    let f = |n| floats(text, n, kind);
    let i = |n| ints(text, n, kind);
    Ok(match kind {
        "string" => V::Text(Text::from_slice_unchecked(text.as_bytes())),
        "int" => V::I32(i(1)?[0]),
        "float" => V::F32(f(1)?[0]),
        "double" => {
            let v = text.trim().parse::<f64>().ok().filter(|v| v.is_finite());
            V::F64(v.ok_or_else(|| format!("'{text}' is not a finite double"))?)
        }
        "v2i" => {
            let v = i(2)?;
            V::IntVec2(Vec2(v[0], v[1]))
        }
        "v2f" => {
            let v = f(2)?;
            V::FloatVec2(Vec2(v[0], v[1]))
        }
        "v3i" => {
            let v = i(3)?;
            V::IntVec3((v[0], v[1], v[2]))
        }
        "v3f" => {
            let v = f(3)?;
            V::FloatVec3((v[0], v[1], v[2]))
        }
        "box2i" => {
            let v = i(4)?;
            let size = (
                i64::from(v[2]) - i64::from(v[0]) + 1,
                i64::from(v[3]) - i64::from(v[1]) + 1,
            );
            if size.0 < 0 || size.1 < 0 {
                return Err(format!("box2i '{text}': the maximum is below the minimum"));
            }
            V::IntegerBounds(IntegerBounds::new(
                Vec2(v[0], v[1]),
                Vec2(size.0 as usize, size.1 as usize),
            ))
        }
        "box2f" => {
            let v = f(4)?;
            V::FloatRect(FloatRect {
                min: Vec2(v[0], v[1]),
                max: Vec2(v[2], v[3]),
            })
        }
        "m33f" => V::Matrix3x3(f(9)?.try_into().expect("nine values")),
        "m44f" => V::Matrix4x4(f(16)?.try_into().expect("sixteen values")),
        "rational" => V::Rational(parse_rational(text)?),
        "timecode" => V::TimeCode(timecode::parse(text)?),
        "keycode" => V::KeyCode(key_code(&i(7)?)?),
        other => unreachable!("type {other} is not in TYPES"),
    })
}

/// Exactly `count` comma-separated numbers.
fn numbers<T: std::str::FromStr>(text: &str, count: usize, kind: &str) -> Result<Vec<T>, String> {
    let values: Vec<T> = text
        .split(',')
        .map(|v| v.trim().parse::<T>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("'{text}' is not of type {kind}: {}", written(count)))?;
    match values.len() == count {
        true => Ok(values),
        false => Err(format!(
            "'{text}' has {} values where a {kind} has {count}: {}",
            values.len(),
            written(count)
        )),
    }
}

fn written(count: usize) -> String {
    match count {
        1 => "write one number".to_string(),
        _ => format!("write {count} numbers separated by commas"),
    }
}

fn ints(text: &str, count: usize, kind: &str) -> Result<Vec<i32>, String> {
    numbers(text, count, kind)
}

/// Floats, each finite (a NaN or infinity is a slip, as for every number
/// exrcomp takes).
fn floats(text: &str, count: usize, kind: &str) -> Result<Vec<f32>, String> {
    let values: Vec<f32> = numbers(text, count, kind)?;
    match values.iter().all(|v| v.is_finite()) {
        true => Ok(values),
        false => Err(format!(
            "'{text}': every value of a {kind} must be a finite float"
        )),
    }
}

/// OpenEXR's KeyCode: manufacturer, film type, prefix, count, perforation
/// offset, perforations per frame and per count, each in ImfKeyCode.h's
/// range (OpenEXR refuses a file with one outside it).
fn key_code(v: &[i32]) -> Result<KeyCode, String> {
    let fields = [
        ("film manufacturer code", 0, 99),
        ("film type", 0, 99),
        ("prefix", 0, 999_999),
        ("count", 0, 9999),
        ("perforation offset", 0, 119),
        ("perforations per frame", 1, 15),
        ("perforations per count", 20, 120),
    ];
    for (&value, (what, min, max)) in v.iter().zip(fields) {
        if !(min..=max).contains(&value) {
            return Err(format!(
                "keycode {what} {value} is outside OpenEXR's {min}-{max} (the seven fields: \
                 manufacturer, type, prefix, count, perf offset, perfs per frame, perfs per count)"
            ));
        }
    }
    Ok(KeyCode {
        film_manufacturer_code: v[0],
        film_type: v[1],
        film_roll_prefix: v[2],
        count: v[3],
        perforation_offset: v[4],
        perforations_per_frame: v[5],
        perforations_per_count: v[6],
    })
}

/// A rate or ratio: `N`, `N/D`, or a decimal: the NTSC rates as their
/// exact fractions (23.976 is 24000/1001), others exactly (12.5 is 25/2).
pub fn parse_rational(text: &str) -> Result<Rational, String> {
    let bad = || format!("'{text}' is not a rational: write N, N/D (24000/1001) or 23.976");
    let text = text.trim();
    if let Some((n, d)) = text.split_once('/') {
        let n: i32 = n.trim().parse().map_err(|_| bad())?;
        let d: u32 = n_over(d.trim()).ok_or_else(bad)?;
        return Ok((n, d));
    }
    let ntsc = [
        ("23.976", 24000),
        ("23.98", 24000),
        ("29.97", 30000),
        ("47.952", 48000),
        ("59.94", 60000),
    ];
    if let Some(&(_, n)) = ntsc.iter().find(|(t, _)| *t == text) {
        return Ok((n, 1001));
    }
    let (whole, fraction) = text.split_once('.').unwrap_or((text, ""));
    if fraction.len() > 6 || !fraction.bytes().all(|b| b.is_ascii_digit()) {
        return Err(bad());
    }
    let scale = 10i64.pow(fraction.len() as u32);
    let digits = format!("{whole}{fraction}");
    let n: i64 = digits.parse().map_err(|_| bad())?;
    let divisor = gcd(n.unsigned_abs(), scale as u64) as i64;
    let (n, d) = (n / divisor, scale / divisor);
    Ok((i32::try_from(n).map_err(|_| bad())?, d as u32))
}

/// `--fps`: a rational (`parse_rational`) above zero.
pub fn parse_fps(text: &str) -> Result<Rational, String> {
    let fps = parse_rational(text)?;
    match fps.0 > 0 {
        true => Ok(fps),
        false => Err(format!("a frame rate is above 0, not {text}")),
    }
}

fn n_over(d: &str) -> Option<u32> {
    d.parse::<u32>().ok().filter(|&d| d > 0)
}

fn gcd(mut a: u64, mut b: u64) -> u64 {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// One `--erase-attrib`: a name, or a glob (`*` any run of characters, `?`
/// one) over names, matched case by case as OpenEXR names are. A name
/// exrcomp owns is refused; a glob passes over those.
pub fn parse_erase(text: &str) -> Result<String, String> {
    check_name(text)?;
    if !text.contains(['*', '?']) {
        if let Some(why) = owned(text) {
            return Err(format!("'{text}' cannot be erased: {why}"));
        }
        if required(text) {
            return Err(format!(
                "'{text}' cannot be erased: every OpenEXR header has it (set it instead)"
            ));
        }
    }
    Ok(text.to_string())
}

/// Whether `name` matches glob `pattern`.
fn matches(pattern: &[u8], name: &[u8]) -> bool {
    let (mut p, mut n) = (0, 0);
    // Where the last `*` was, and the name position it matched up to.
    let mut star: Option<(usize, usize)> = None;
    while n < name.len() {
        match pattern.get(p) {
            Some(b'*') => {
                star = Some((p, n));
                p += 1;
            }
            Some(&c) if c == b'?' || c == name[n] => {
                p += 1;
                n += 1;
            }
            _ => match star {
                Some((sp, sn)) => {
                    p = sp + 1;
                    n = sn + 1;
                    star = Some((sp, sn + 1));
                }
                None => return false,
            },
        }
    }
    pattern[p..].iter().all(|&c| c == b'*')
}

/// Everything the user asks of the output's attributes.
#[derive(Clone, Debug, Default)]
pub struct Edits {
    /// Names and globs, erased first.
    pub erase: Vec<String>,
    /// Set in order after the erasures (and `--fps` as `framesPerSecond`).
    pub set: Vec<Attrib>,
    pub timecode: Option<TimecodeSpec>,
}

impl Edits {
    /// The edits, `--fps` among the attributes set; the same attribute
    /// from two options is refused.
    pub fn new(
        erase: Vec<String>,
        mut set: Vec<Attrib>,
        fps: Option<Rational>,
        timecode: Option<TimecodeSpec>,
    ) -> Result<Self, String> {
        let given = |name: &str| set.iter().any(|a| a.name == name);
        if fps.is_some() && given("framesPerSecond") {
            return Err(
                "--fps and --attrib framesPerSecond both set the frame rate: give one".into(),
            );
        }
        if timecode.is_some() && given("timeCode") {
            return Err("--timecode and --attrib timeCode both set the timecode: give one".into());
        }
        if let Some(fps) = fps {
            set.push(Attrib {
                name: "framesPerSecond".into(),
                value: AttributeValue::Rational(fps),
            });
        }
        Ok(Edits {
            erase,
            set,
            timecode,
        })
    }

    /// Whether a `--timecode` start is still to be given its frame.
    pub fn needs_anchor(&self) -> bool {
        matches!(self.timecode, Some(TimecodeSpec::Start { at: None, .. }))
    }

    /// A `--timecode` start without `@FRAME` is the timecode of `first`.
    pub fn anchor(&mut self, first: i64) {
        if let Some(TimecodeSpec::Start { at: at @ None, .. }) = &mut self.timecode {
            *at = Some(first);
        }
    }

    /// Removes the attributes `--erase-attrib` names from `header`, but
    /// those exrcomp owns and those every header has.
    pub fn erase(&self, header: &mut Header) {
        if self.erase.is_empty() {
            return;
        }
        let names: Vec<Vec<u8>> = header
            .all_named_attributes()
            .map(|(name, _)| name.to_vec())
            .collect();
        for name in names {
            let text = String::from_utf8_lossy(&name);
            let erasable = owned(&text).is_none() && !required(&text);
            if erasable && self.erase.iter().any(|p| matches(p.as_bytes(), &name)) {
                remove(header, &name);
            }
        }
    }

    /// Another part of the file `written` heads, edited as it was: erased,
    /// set, and given its timecode (OpenEXR shares `timeCode` between the
    /// parts of a file).
    pub fn carry(&self, part: &mut Header, written: &Header) {
        self.erase(part);
        self.set_attributes(part);
        if self.timecode.is_some() {
            if let Some(code) = find(written, b"timeCode") {
                set(part, "timeCode", code);
            }
        }
    }

    fn set_attributes(&self, header: &mut Header) {
        for attrib in &self.set {
            set(header, &attrib.name, attrib.value.clone());
        }
    }

    /// Sets the attributes asked for in `header`, then the timecode of
    /// output frame `frame`, counted at the header's `framesPerSecond`.
    pub fn set(&self, header: &mut Header, frame: i64) -> Result<(), String> {
        self.set_attributes(header);
        let Some(spec) = self.timecode else {
            return Ok(());
        };
        let fps = match find(header, b"framesPerSecond") {
            Some(AttributeValue::Rational(fps)) => fps,
            _ => {
                return Err(
                    "--timecode counts frames at the frame rate, and the header has no \
                            framesPerSecond: give --fps"
                        .into(),
                )
            }
        };
        let code = match spec {
            TimecodeSpec::Start { code, at } => {
                let at = at.ok_or("a --timecode start without its frame (internal)")?;
                Counting::new(fps, code.drop_frame)?
                    .shift(&code, i128::from(frame) - i128::from(at))?
            }
            TimecodeSpec::Shift(frames) => {
                let Some(AttributeValue::TimeCode(old)) = find(header, b"timeCode") else {
                    return Err(format!(
                        "--timecode {frames:+} shifts the input's timeCode, and its header has \
                         none: give a start (--timecode 01:00:00:00)"
                    ));
                };
                Counting::new(fps, old.drop_frame)?.shift(&old, frames.into())?
            }
        };
        set(header, "timeCode", AttributeValue::TimeCode(code));
        Ok(())
    }
}

/// An attribute an operation writes on its output's header or removes
/// from it (`Op::attributes`: a colour conversion's destination), before
/// the user's edits.
#[derive(Clone, Debug, PartialEq)]
pub enum Edit {
    Set(&'static str, Box<AttributeValue>),
    Remove(&'static str),
}

impl Edit {
    pub fn apply(&self, header: &mut Header) {
        match self {
            Edit::Set(name, value) => set(header, name, (**value).clone()),
            Edit::Remove(name) => remove(header, name.as_bytes()),
        }
    }
}

/// The value of attribute `name` in `header`, wherever the crate keeps it.
fn find(header: &Header, name: &[u8]) -> Option<AttributeValue> {
    header
        .all_named_attributes()
        .find(|(n, _)| *n == name)
        .map(|(_, value)| value)
}

/// `name` set to `value`, replacing any attribute of that name. The three
/// every header has are fields of the crate's header; any other goes in its
/// list of other attributes, which the writer writes as any attribute.
fn set(header: &mut Header, name: &str, value: AttributeValue) {
    use AttributeValue as V;
    match (name, value) {
        ("pixelAspectRatio", V::F32(v)) => header.shared_attributes.pixel_aspect = v,
        ("screenWindowWidth", V::F32(v)) => header.own_attributes.screen_window_width = v,
        ("screenWindowCenter", V::FloatVec2(v)) => header.own_attributes.screen_window_center = v,
        ("chromaticities", V::Chromaticities(v)) => {
            header.shared_attributes.chromaticities = Some(v)
        }
        (name, value) => {
            remove(header, name.as_bytes());
            let name = Text::from_slice_unchecked(name.as_bytes());
            header.own_attributes.other.insert(name, value);
        }
    }
}

/// Removes attribute `name` from `header`: from the lists of other
/// attributes, or the crate's field for it (it reads each standard
/// attribute of the standard type into one).
fn remove(header: &mut Header, name: &[u8]) {
    let key = Text::from_slice_unchecked(name);
    let (own, shared) = (&mut header.own_attributes, &mut header.shared_attributes);
    own.other.remove(&key);
    shared.other.remove(&key);
    match name {
        b"chromaticities" => shared.chromaticities = None,
        b"timeCode" => shared.time_code = None,
        b"whiteLuminance" => own.white_luminance = None,
        b"adoptedNeutral" => own.adopted_neutral = None,
        b"renderingTransform" => own.rendering_transform_name = None,
        b"lookModTransform" => own.look_modification_transform_name = None,
        b"xDensity" => own.horizontal_density = None,
        b"owner" => own.owner = None,
        b"comments" => own.comments = None,
        b"capDate" => own.capture_date = None,
        b"utcOffset" => own.utc_offset = None,
        b"longitude" => own.longitude = None,
        b"latitude" => own.latitude = None,
        b"altitude" => own.altitude = None,
        b"focus" => own.focus = None,
        b"expTime" => own.exposure = None,
        b"aperture" => own.aperture = None,
        b"isoSpeed" => own.iso_speed = None,
        b"envmap" => own.environment_map = None,
        b"keyCode" => own.film_key_code = None,
        b"wrapmodes" => own.wrap_mode_name = None,
        b"framesPerSecond" => own.frames_per_second = None,
        b"worldToCamera" => own.world_to_camera = None,
        b"worldToNDC" => own.world_to_normalized_device = None,
        b"originalDataWindow" => own.original_data_window = None,
        b"near" => own.near_clip_plane = None,
        b"far" => own.far_clip_plane = None,
        b"fieldOfViewHorizontal" => own.horizontal_field_of_view = None,
        b"fieldOfViewVertical" => own.vertical_field_of_view = None,
        b"software" => own.software_name = None,
        _ => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use AttributeValue as V;

    fn value(text: &str) -> AttributeValue {
        parse_attrib(text).unwrap().value
    }

    fn refusal(text: &str) -> String {
        parse_attrib(text).unwrap_err()
    }

    #[test]
    fn types_are_inferred_as_oiiotool_infers_them() {
        // oiiotool 2.4: 42, -3 and +3 int; 1.5, .5, 1e5 float; the rest string.
        assert_eq!(value("a=42"), V::I32(42));
        assert_eq!(value("a=-3"), V::I32(-3));
        assert_eq!(value("a=+3"), V::I32(3));
        assert_eq!(value("a=1.5"), V::F32(1.5));
        assert_eq!(value("a=.5"), V::F32(0.5));
        assert_eq!(value("a=1e5"), V::F32(1e5));
        for text in [
            "abc",
            "1,2",
            "1/2",
            "01:00:00:00",
            "inf",
            "nan",
            "1_000",
            "",
        ] {
            let expected = V::Text(Text::from_slice_unchecked(text.as_bytes()));
            assert_eq!(value(&format!("a={text}")), expected, "{text}");
        }
        // oiiotool clamps this to 2147483647; here it is refused.
        assert!(refusal("a=3000000000").contains("is not of type int"));
    }

    #[test]
    fn a_type_suffix_types_the_value() {
        assert_eq!(value("a=0:string"), V::Text(Text::from("0")));
        assert_eq!(value("a=0.25:double"), V::F64(0.25));
        assert_eq!(value("a=1, 2:v2i"), V::IntVec2(Vec2(1, 2)));
        assert_eq!(value("a=1,2.5:v2f"), V::FloatVec2(Vec2(1.0, 2.5)));
        assert_eq!(value("a=1,2,3:v3i"), V::IntVec3((1, 2, 3)));
        assert_eq!(value("a=1,2,3:v3f"), V::FloatVec3((1.0, 2.0, 3.0)));
        assert_eq!(
            value("a=-1,2,10,20:box2i"),
            V::IntegerBounds(IntegerBounds::new(Vec2(-1, 2), Vec2(12, 19)))
        );
        assert_eq!(
            value("a=0,0,1.5,2:box2f"),
            V::FloatRect(FloatRect {
                min: Vec2(0.0, 0.0),
                max: Vec2(1.5, 2.0)
            })
        );
        let identity = "1,0,0,0,1,0,0,0,1";
        assert_eq!(
            value(&format!("a={identity}:m33f")),
            V::Matrix3x3([1., 0., 0., 0., 1., 0., 0., 0., 1.])
        );
        assert!(
            matches!(value(&format!("a={}:m44f", ["2"; 16].join(","))), V::Matrix4x4(m) if m == [2.0; 16])
        );
        assert_eq!(value("a=24000/1001:rational"), V::Rational((24000, 1001)));
        assert_eq!(
            value("a=1,2,3,4,5,6,64:keycode"),
            V::KeyCode(KeyCode {
                film_manufacturer_code: 1,
                film_type: 2,
                film_roll_prefix: 3,
                count: 4,
                perforation_offset: 5,
                perforations_per_frame: 6,
                perforations_per_count: 64,
            })
        );
        // Not a type name: part of the value.
        assert_eq!(value("a=b:c"), V::Text(Text::from("b:c")));
        assert_eq!(value("a=x:int:string"), V::Text(Text::from("x:int")));
    }

    #[test]
    fn standard_attributes_keep_their_types() {
        assert_eq!(value("expTime=1"), V::F32(1.0));
        assert_eq!(value("owner=42"), V::Text(Text::from("42")));
        assert_eq!(value("framesPerSecond=24"), V::Rational((24, 1)));
        assert_eq!(value("framesPerSecond=23.976"), V::Rational((24000, 1001)));
        assert!(matches!(value("timeCode=01:00:00:00"), V::TimeCode(_)));
        assert_eq!(
            value("screenWindowCenter=0.5,0"),
            V::FloatVec2(Vec2(0.5, 0.0))
        );
        assert!(refusal("expTime=1:int").contains("standard attribute of type float"));
        assert!(refusal("chromaticities=1").contains("does not write"));
    }

    #[test]
    fn bad_values_are_refused_in_one_line() {
        for (text, says) in [
            ("a", "expected NAME=VALUE"),
            ("=1", "1 to 255 bytes"),
            ("a=x:float", "is not of type float"),
            ("a=nan:float", "finite"),
            ("a=1e39:float", "finite"),
            ("a=1,2:v3f", "has 2 values where a v3f has 3"),
            ("a=3,0,1,0:box2i", "maximum is below the minimum"),
            ("a=1/0:rational", "not a rational"),
            ("a=1.2345678:rational", "not a rational"),
            ("a=25:00:00:00:timecode", "hours 25 is over 23"),
            ("a=1,2,3,4,5,16,64:keycode", "perforations per frame 16"),
            ("dataWindow=0,0,1,1:box2i", "cannot be set"),
            ("channels=R", "cannot be set"),
            ("Software=me", "provenance"),
        ] {
            let message = refusal(text);
            assert!(message.contains(says), "{text}: {message}");
            assert!(!message.contains('\n'), "{text}");
        }
        assert!(parse_attrib(&format!("{}=1", "n".repeat(256))).is_err());
    }

    #[test]
    fn rationals() {
        assert_eq!(parse_rational("24").unwrap(), (24, 1));
        assert_eq!(parse_rational("-3/4").unwrap(), (-3, 4));
        assert_eq!(parse_rational("12.5").unwrap(), (25, 2));
        assert_eq!(parse_rational("29.97").unwrap(), (30000, 1001));
        assert!(parse_rational("x").is_err());
        assert!(parse_rational("1/-2").is_err());
    }

    #[test]
    fn globs() {
        assert!(matches(b"Exif:*", b"Exif:ImageHistory"));
        assert!(matches(b"*", b""));
        assert!(matches(b"a?c", b"abc"));
        assert!(matches(b"*story", b"Exif:ImageHistory"));
        assert!(matches(b"a*b*c", b"aXbYbZc"));
        assert!(!matches(b"a*b*c", b"aXbYbZ"));
        assert!(!matches(b"software", b"Software"));
        assert!(!matches(b"own", b"owner"));
        assert!(parse_erase("dataWindow").is_err());
        assert!(parse_erase("pixelAspectRatio").is_err());
        assert!(parse_erase("*").is_ok());
        assert!(parse_erase("Software").is_ok());
    }

    fn header() -> Header {
        Header::new(Text::from("rgba"), Vec2(4, 4), Default::default())
    }

    fn names(header: &Header) -> Vec<String> {
        let mut names: Vec<String> = header
            .all_named_attributes()
            .map(|(n, _)| String::from_utf8_lossy(n).into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn edits_replace_erase_and_keep_what_exrcomp_owns() {
        let mut header = header();
        header.own_attributes.owner = Some(Text::from("them"));
        header.own_attributes.comments = Some(Text::from("old"));
        let set = vec![
            parse_attrib("owner=me").unwrap(),
            parse_attrib("shot=010").unwrap(),
        ];
        let edits = Edits::new(vec!["comm*".into(), "*Window*".into()], set, None, None).unwrap();
        edits.erase(&mut header);
        edits.set(&mut header, 1).unwrap();
        let all = names(&header);
        assert!(!all.contains(&"comments".to_string()));
        // Owned and required attributes pass under a glob.
        for kept in [
            "dataWindow",
            "displayWindow",
            "screenWindowCenter",
            "screenWindowWidth",
        ] {
            assert!(all.contains(&kept.to_string()), "{kept}");
        }
        // Set once, not beside the crate's own field.
        assert_eq!(all.iter().filter(|n| *n == "owner").count(), 1);
        assert_eq!(find(&header, b"owner"), Some(V::Text(Text::from("me"))));
        assert_eq!(find(&header, b"shot"), Some(V::I32(10)));
        // The three every header has are the crate's fields.
        let aspect = Edits::new(
            vec![],
            vec![parse_attrib("pixelAspectRatio=2").unwrap()],
            None,
            None,
        )
        .unwrap();
        aspect.set(&mut header, 1).unwrap();
        assert_eq!(header.shared_attributes.pixel_aspect, 2.0);
        assert_eq!(
            names(&header)
                .iter()
                .filter(|n| *n == "pixelAspectRatio")
                .count(),
            1
        );
    }

    #[test]
    fn each_frame_gets_its_timecode() {
        let start = timecode::parse_spec("00:59:59:22").unwrap();
        let mut edits = Edits::new(vec![], vec![], Some((24, 1)), Some(start)).unwrap();
        assert!(edits.needs_anchor());
        edits.anchor(1001);
        let at = |frame| {
            let mut header = header();
            edits.set(&mut header, frame).unwrap();
            match find(&header, b"timeCode") {
                Some(V::TimeCode(code)) => timecode::display(&code),
                other => panic!("{other:?}"),
            }
        };
        assert_eq!(at(1001), "00:59:59:22");
        assert_eq!(at(1003), "01:00:00:00");
        assert_eq!(at(1000), "00:59:59:21");
        // Shifting the input's own timecode.
        let shift = Edits::new(vec![], vec![], None, Some(TimecodeSpec::Shift(-24))).unwrap();
        let mut header = header();
        header.own_attributes.frames_per_second = Some((24, 1));
        let missing = shift.set(&mut header.clone(), 1).unwrap_err();
        assert!(missing.contains("has none"), "{missing}");
        header.shared_attributes.time_code = Some(timecode::parse("10:00:00:00").unwrap());
        shift.set(&mut header, 1).unwrap();
        assert!(
            matches!(find(&header, b"timeCode"), Some(V::TimeCode(c)) if timecode::display(&c) == "09:59:59:00")
        );
        assert_eq!(
            names(&header).iter().filter(|n| *n == "timeCode").count(),
            1
        );
        // No rate, no counting.
        let no_rate = Edits::new(vec![], vec![], None, Some(TimecodeSpec::Shift(1))).unwrap();
        assert!(no_rate
            .set(&mut self::header(), 1)
            .unwrap_err()
            .contains("--fps"));
        assert!(Edits::new(
            vec![],
            vec![parse_attrib("timeCode=01:00:00:00").unwrap()],
            None,
            Some(start)
        )
        .is_err());
        assert!(Edits::new(
            vec![],
            vec![parse_attrib("framesPerSecond=24").unwrap()],
            Some((24, 1)),
            None
        )
        .is_err());
    }
}
