//! SMPTE timecode as OpenEXR's `timeCode` attribute holds it (ImfTimeCode.h:
//! hours, minutes, seconds and frame in BCD with their flags in one int, the
//! eight binary groups of user data in another; the exr crate packs them),
//! written `HH:MM:SS:FF` (`HH:MM:SS;FF` drop-frame), and counted in frames
//! at a frame rate so that each output frame gets its own.

use exr::meta::attribute::{Rational, TimeCode};

/// What `--timecode` asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TimecodeSpec {
    /// `HH:MM:SS:FF[@FRAME]`: the timecode of output frame `at`, the others
    /// counted from it; `at` is the shot's first frame when not given.
    Start { code: TimeCode, at: Option<i64> },
    /// `+N` or `-N`: the header source's own timecode, N frames later.
    Shift(i64),
}

/// `HH:MM:SS:FF`, `HH:MM:SS;FF` (drop-frame), `...@FRAME`, or `+N` / `-N`.
pub fn parse_spec(text: &str) -> Result<TimecodeSpec, String> {
    let text = text.trim();
    if let Some(sign) = text.chars().next().filter(|c| *c == '+' || *c == '-') {
        let frames: i64 = text[1..]
            .parse()
            .ok()
            .filter(|n: &i64| *n <= MAX_SHIFT)
            .ok_or_else(|| format!("'{text}': a shift is {sign}N frames, N at most {MAX_SHIFT}"))?;
        return Ok(TimecodeSpec::Shift(if sign == '-' {
            -frames
        } else {
            frames
        }));
    }
    let (code, at) = match text.split_once('@') {
        Some((code, frame)) => {
            let frame = frame.trim().parse::<i64>().map_err(|_| {
                format!("'{text}': the frame after @ is a frame number (01:00:00:00@1001)")
            })?;
            (code, Some(frame))
        }
        None => (text, None),
    };
    Ok(TimecodeSpec::Start {
        code: parse(code)?,
        at,
    })
}

/// Longest shift taken: a day of frames at 30 fps, ten times over.
const MAX_SHIFT: i64 = 10 * 24 * 3600 * 30;

/// A timecode typed as `HH:MM:SS:FF`, or `HH:MM:SS;FF` for drop-frame
/// (SMPTE's separator), each field in OpenEXR's range: hours 0-23, minutes
/// and seconds 0-59, frame 0-29. Flags and user data are 0 but drop frame.
pub fn parse(text: &str) -> Result<TimeCode, String> {
    let bad = || format!("'{text}' is not a timecode: write HH:MM:SS:FF (HH:MM:SS;FF drop-frame)");
    let text = text.trim();
    let drop_frame = text.contains(';');
    let fields: Vec<u8> = text
        .split([':', ';'])
        .map(|f| match f.len() {
            1 | 2 if f.bytes().all(|b| b.is_ascii_digit()) => f.parse().map_err(|_| bad()),
            _ => Err(bad()),
        })
        .collect::<Result<_, _>>()?;
    let [hours, minutes, seconds, frame] = fields[..] else {
        return Err(bad());
    };
    if drop_frame && text.find(';') != text.rfind([':', ';']) {
        return Err(bad());
    }
    for (value, max, what) in [
        (hours, 23, "hours"),
        (minutes, 59, "minutes"),
        (seconds, 59, "seconds"),
        (frame, 29, "frame"),
    ] {
        if value > max {
            return Err(format!(
                "timecode '{text}': {what} {value} is over {max} (OpenEXR's range)"
            ));
        }
    }
    Ok(TimeCode {
        hours,
        minutes,
        seconds,
        frame,
        drop_frame,
        ..TimeCode::default()
    })
}

/// How a frame rate counts timecode frames: `rate` frames to a timecode
/// second (the rate rounded), and at 29.97 fps drop-frame counting, which
/// skips frame numbers 0 and 1 of every minute but each tenth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Counting {
    rate: i64,
    drop: bool,
}

impl Counting {
    /// The counting at `fps` frames per second (OpenEXR's `framesPerSecond`),
    /// drop-frame when `drop` (only at 30000/1001).
    pub fn new(fps: Rational, drop: bool) -> Result<Self, String> {
        let (n, d) = (fps.0 as f64, fps.1 as f64);
        let rate = (n / d).round();
        if !(d > 0.0 && (1.0..=30.0).contains(&rate)) {
            return Err(format!(
                "timecode at {}/{} fps: OpenEXR's timecode counts frames 0-29, so rates \
                 from 1 to 30 fps",
                fps.0, fps.1
            ));
        }
        if drop && fps != (30000, 1001) {
            return Err(format!(
                "drop-frame timecode (HH:MM:SS;FF) counts 29.97 fps (30000/1001), not {}/{}",
                fps.0, fps.1
            ));
        }
        Ok(Counting {
            rate: rate as i64,
            drop,
        })
    }

    fn frames_per_day(self) -> i64 {
        match self.drop {
            // 17982 frames every ten minutes.
            true => 144 * 17982,
            false => 24 * 3600 * self.rate,
        }
    }

    /// Frames since 00:00:00:00 of `code`, which must exist in this counting.
    pub fn frames(self, code: &TimeCode) -> Result<i64, String> {
        let [h, m, s, f] = [code.hours, code.minutes, code.seconds, code.frame].map(i64::from);
        let shown = display(code);
        if f >= self.rate {
            return Err(format!(
                "timecode {shown}: frame {f} does not exist at {} frames a second",
                self.rate
            ));
        }
        let seconds = (h * 60 + m) * 60 + s;
        if !self.drop {
            return Ok(seconds * self.rate + f);
        }
        if s == 0 && f < 2 && m % 10 != 0 {
            return Err(format!(
                "timecode {shown} does not exist in drop-frame counting (frames 0 and 1 of \
                 each minute but every tenth are skipped)"
            ));
        }
        let minutes = h * 60 + m;
        Ok(seconds * 30 + f - 2 * (minutes - minutes / 10))
    }

    /// `code` moved by `frames` frames, wrapping around midnight; its flags
    /// and user data kept. Wide, so that any two i64 frames' difference
    /// (`--frames` near i64's ends against an `@FRAME` anchor) is exact.
    pub fn shift(self, code: &TimeCode, frames: i128) -> Result<TimeCode, String> {
        let day = self.frames_per_day();
        let within = frames.rem_euclid(i128::from(day)) as i64;
        let mut n = (self.frames(code)? + within).rem_euclid(day);
        if self.drop {
            let (tens, rest) = (n / 17982, n % 17982);
            n += 18 * tens + if rest > 1 { 2 * ((rest - 2) / 1798) } else { 0 };
        }
        let seconds = n / self.rate;
        Ok(TimeCode {
            hours: (seconds / 3600 % 24) as u8,
            minutes: (seconds / 60 % 60) as u8,
            seconds: (seconds % 60) as u8,
            frame: (n % self.rate) as u8,
            ..*code
        })
    }
}

/// `HH:MM:SS:FF` (`;FF` when drop-frame), for messages.
pub fn display(code: &TimeCode) -> String {
    let separator = if code.drop_frame { ';' } else { ':' };
    format!(
        "{:02}:{:02}:{:02}{separator}{:02}",
        code.hours, code.minutes, code.seconds, code.frame
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use exr::meta::attribute::AttributeValue;

    fn code(text: &str) -> TimeCode {
        parse(text).unwrap()
    }

    /// The attribute's bytes as the writer puts them in a file: the name,
    /// the type, the size, then the two ints.
    fn packed(code: TimeCode) -> (u32, u32) {
        let mut bytes = Vec::new();
        exr::meta::attribute::write(b"timeCode", &AttributeValue::TimeCode(code), &mut bytes)
            .unwrap();
        let value = &bytes[bytes.len() - 8..];
        let int = |b: &[u8]| u32::from_le_bytes(b.try_into().unwrap());
        assert_eq!(&bytes[..18], b"timeCode\0timecode\0");
        (int(&value[..4]), int(&value[4..]))
    }

    #[test]
    fn packing_is_openexrs() {
        // ImfTimeCode.h: frame units bits 0-3, tens 4-5, drop frame 6, colour
        // frame 7, seconds 8-14, field/phase 15, minutes 16-22, bgf0 23,
        // hours 24-29, bgf1 30, bgf2 31; binary group n at bits 4(n-1)..4n-1.
        assert_eq!(packed(code("01:02:03:04")), (0x0102_0304, 0));
        assert_eq!(packed(code("23:59:59:29")), (0x2359_5929, 0));
        assert_eq!(packed(code("10:00:00;02")), (0x1000_0042, 0));
        let flagged = TimeCode {
            color_frame: true,
            field_phase: true,
            binary_group_flags: [true, true, true],
            binary_groups: [1, 2, 3, 4, 5, 6, 7, 15],
            ..code("00:00:00:00")
        };
        assert_eq!(packed(flagged), (0xC080_8080, 0xF765_4321));
    }

    #[test]
    fn typed_timecodes() {
        assert!(parse("01:00:00:00").is_ok());
        assert!(code("01:00:00;00").drop_frame);
        for bad in [
            "1:00:00",
            "24:00:00:00",
            "00:60:00:00",
            "00:00:00:30",
            "aa:00:00:00",
        ] {
            assert!(parse(bad).is_err(), "{bad}");
        }
        assert!(parse("01;00:00:00").is_err());
        assert_eq!(
            parse_spec("01:00:00:00@1001").unwrap(),
            TimecodeSpec::Start {
                code: code("01:00:00:00"),
                at: Some(1001)
            }
        );
        assert_eq!(parse_spec("-24").unwrap(), TimecodeSpec::Shift(-24));
        assert_eq!(parse_spec("+3").unwrap(), TimecodeSpec::Shift(3));
        assert!(parse_spec("+x").is_err());
        assert!(parse_spec("01:00:00:00@x").is_err());
    }

    #[test]
    fn counting_at_whole_rates() {
        let at24 = Counting::new((24, 1), false).unwrap();
        let shown = |c: TimeCode| display(&c);
        assert_eq!(at24.frames(&code("01:00:00:00")).unwrap(), 86400);
        assert_eq!(
            shown(at24.shift(&code("00:59:59:23"), 1).unwrap()),
            "01:00:00:00"
        );
        assert_eq!(
            shown(at24.shift(&code("00:00:00:00"), -1).unwrap()),
            "23:59:59:23"
        );
        assert_eq!(
            shown(at24.shift(&code("23:59:59:23"), 1).unwrap()),
            "00:00:00:00"
        );
        assert!(at24.frames(&code("00:00:00:24")).is_err());
        // 23.976 counts 24 frames a second, non-drop.
        let ntsc_film = Counting::new((24000, 1001), false).unwrap();
        assert_eq!(ntsc_film, at24);
        assert!(Counting::new((48, 1), false).is_err());
        assert!(Counting::new((24, 1), true).is_err());
        assert!(Counting::new((24, 0), false).is_err());
    }

    #[test]
    fn drop_frame_skips_two_numbers_a_minute_but_every_tenth() {
        let df = Counting::new((30000, 1001), true).unwrap();
        let after = |text: &str, n: i64| display(&df.shift(&code(text), n.into()).unwrap());
        assert_eq!(after("00:00:59;29", 1), "00:01:00;02");
        assert_eq!(after("00:09:59;29", 1), "00:10:00;00");
        assert_eq!(after("00:01:00;02", -1), "00:00:59;29");
        // 17982 frames every ten minutes, 107892 an hour.
        assert_eq!(after("00:00:00;00", 17982), "00:10:00;00");
        assert_eq!(df.frames(&code("01:00:00;00")).unwrap(), 107892);
        assert!(df.frames(&code("00:01:00;00")).is_err());
        assert!(df.frames(&code("00:10:00;00")).is_ok());
        // Every frame of a day round-trips.
        for n in (0..144 * 17982i64).step_by(7) {
            let tc = df.shift(&code("00:00:00;00"), n.into()).unwrap();
            assert_eq!(df.frames(&tc).unwrap(), n);
        }
    }

    #[test]
    fn shifts_of_any_two_frames_apart_are_exact() {
        let at24 = Counting::new((24, 1), false).unwrap();
        let start = code("00:00:00:00");
        // i64::MAX - (-1e9) frames, modulo a day of 2,073,600: 235,007.
        let far = i128::from(i64::MAX) + 1_000_000_000;
        assert_eq!(display(&at24.shift(&start, far).unwrap()), "02:43:11:23");
        let back = i128::from(i64::MIN) - i128::from(i64::MAX);
        let expected = back.rem_euclid(2_073_600) as i64;
        assert_eq!(
            at24.frames(&at24.shift(&start, back).unwrap()).unwrap(),
            expected
        );
    }

    #[test]
    fn shifting_keeps_flags_and_user_data() {
        let at25 = Counting::new((25, 1), false).unwrap();
        let tagged = TimeCode {
            color_frame: true,
            binary_groups: [9, 0, 0, 0, 0, 0, 0, 1],
            ..code("10:00:00:24")
        };
        let next = at25.shift(&tagged, 1).unwrap();
        assert_eq!(display(&next), "10:00:01:00");
        assert!(next.color_frame);
        assert_eq!(next.binary_groups, tagged.binary_groups);
    }
}
