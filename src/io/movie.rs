//! Review movies (.mov, .mp4; specs/file-format.md, "Review movies"): the
//! review frames `media::Media::convert` makes, streamed in frame order as
//! raw RGB into `ffmpeg` (found on PATH), which encodes them. The movie is
//! one output: ffmpeg writes it under a temporary name, renamed into place
//! by `Movie::finish` once ffmpeg exits 0; anything else (an error, an
//! interruption, a failed frame) kills ffmpeg and removes the temporary.

use super::media::{Bits, Format, Media, Samples, Strip, Transfer};
use crate::error::{Error, Result};
use exr::meta::attribute::{AttributeValue, Rational, TimeCode};
use exr::meta::header::Header;
use std::fs::File;
use std::io::{BufWriter, Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};
use std::sync::Mutex;

/// A movie's video codec (`--codec`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Codec {
    /// Apple ProRes 422 HQ, 10-bit 4:2:2 (.mov's default).
    Prores,
    /// Apple ProRes 4444, 10-bit 4:4:4, with alpha when the image has it.
    Prores4444,
    /// Avid DNxHR 444, 10-bit 4:4:4 (frames at least 256x120): DNxHR HQ
    /// and HQX have half its rate, too few bits for 40 dB on detailed plates.
    Dnxhr,
    /// H.264 (libx264, CRF 14), 8-bit 4:2:0 High (.mp4's default and only
    /// codec), which every player plays.
    H264,
}

impl Codec {
    /// Bits per sample of the frames fed to ffmpeg: 16 for the 10-bit
    /// codecs, 8 (the PNG path's dithered code values) for H.264.
    pub fn bits(self) -> Bits {
        match self {
            Codec::Prores | Codec::Prores4444 | Codec::Dnxhr => Bits::Sixteen,
            Codec::H264 => Bits::Eight,
        }
    }

    /// Whether frames keep their alpha (ProRes 4444 alone carries it).
    pub fn keeps_alpha(self) -> bool {
        self == Codec::Prores4444
    }

    /// The pixel format encoded, and whether its chroma is halved across
    /// (4:2:2, 4:2:0) and down (4:2:0).
    fn pixel_format(self, alpha: bool) -> (&'static str, bool, bool) {
        match (self, alpha) {
            (Codec::Prores, _) => ("yuv422p10le", true, false),
            (Codec::Prores4444, true) => ("yuva444p10le", false, false),
            (Codec::Prores4444, false) => ("yuv444p10le", false, false),
            (Codec::Dnxhr, _) => ("yuv444p10le", false, false),
            (Codec::H264, _) => ("yuv420p", true, true),
        }
    }

    fn encoder(self) -> &'static [&'static str] {
        match self {
            Codec::Prores => &["-c:v", "prores_ks", "-profile:v", "hq", "-vendor", "apl0"],
            Codec::Prores4444 => &["-c:v", "prores_ks", "-profile:v", "4444", "-vendor", "apl0"],
            Codec::Dnxhr => &["-c:v", "dnxhd", "-profile:v", "dnxhr_444"],
            Codec::H264 => &["-c:v", "libx264", "-crf", "14", "-preset", "medium"],
        }
    }
}

/// The container a movie output's extension names: `.mov` or `.mp4`.
pub fn container(name: &str) -> Option<&'static str> {
    let name = name.to_ascii_lowercase();
    [(".mov", "mov"), (".mp4", "mp4")]
        .into_iter()
        .find(|(end, _)| name.ends_with(end))
        .map(|(_, container)| container)
}

/// The frame rate of a movie whose frames give none.
pub const DEFAULT_FPS: Rational = (24, 1);

/// A movie being written: ffmpeg starts with its first frame.
pub struct Movie {
    path: PathBuf,
    container: &'static str,
    pub codec: Codec,
    ffmpeg: PathBuf,
    state: Mutex<State>,
}

impl std::fmt::Debug for Movie {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Movie({}, {:?})", self.container, self.codec)
    }
}

#[derive(Default)]
struct State {
    rate: Option<Rational>,
    timecode: Option<String>,
    encoder: Option<Encoder>,
}

impl Movie {
    /// The movie `path` in `codec` (by default the container's), or why it
    /// cannot be written: ffmpeg missing, or a codec the container lacks.
    pub fn new(path: &Path, codec: Option<Codec>) -> Result<Movie> {
        let name = path.to_string_lossy();
        let container =
            container(&name).ok_or_else(|| Error::internal(format!("{name} is not a movie")))?;
        let codec = codec.unwrap_or(match container {
            "mp4" => Codec::H264,
            _ => Codec::Prores,
        });
        if container == "mp4" && codec != Codec::H264 {
            return Err(Error::usage(format!(
                "{name}: .mp4 movies are H.264; write {codec:?} into a .mov",
            )));
        }
        let ffmpeg = on_path("ffmpeg").ok_or_else(|| {
            Error::usage(format!(
                "{name}: review movies are encoded by ffmpeg, which is not on PATH: \
                 install the package ffmpeg"
            ))
        })?;
        Ok(Movie {
            path: path.to_path_buf(),
            container,
            codec,
            ffmpeg,
            state: Mutex::default(),
        })
    }

    /// How its frames are made: as review frames are, `transfer` (sRGB by
    /// default) into code values of the codec's bits.
    pub fn media(&self, transfer: Option<Transfer>) -> Media {
        Media {
            format: Format::Movie,
            bits: self.codec.bits(),
            quality: super::media::DEFAULT_QUALITY,
            transfer: transfer.unwrap_or(Transfer::Srgb),
            movie_alpha: self.codec.keeps_alpha(),
        }
    }

    /// Takes the movie's frame rate and timecode from `header`, its first
    /// frame's (`framesPerSecond`, else 24; `timeCode`), the timecode one
    /// frame earlier when a slate comes first.
    pub fn time_from(&self, header: &Header, slate: bool) {
        let rate = match super::burn_in::attribute(header, "framesPerSecond") {
            Some(AttributeValue::Rational(rate)) if rate.0 > 0 && rate.1 > 0 => rate,
            _ => DEFAULT_FPS,
        };
        let code = match super::burn_in::attribute(header, "timeCode") {
            Some(AttributeValue::TimeCode(code)) => Some(code),
            _ => None,
        };
        let code = code.and_then(|code| match slate {
            false => Some(code),
            true => earlier(&code, rate),
        });
        let mut state = self.lock();
        state.rate = Some(rate);
        state.timecode = code.as_ref().map(super::timecode::display);
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Streams one frame of `size` (with alpha or not) to ffmpeg, from the
    /// strips `next` yields until `Ok(None)`; the first frame starts it.
    pub fn frame(
        &self,
        frame: Option<i64>,
        size: (usize, usize),
        alpha: bool,
        mut next: impl FnMut() -> Result<Option<Strip>>,
    ) -> Result<()> {
        let mut state = self.lock();
        if state.encoder.is_none() {
            let rate = state.rate.unwrap_or(DEFAULT_FPS);
            let encoder = self.start(size, alpha, rate, state.timecode.as_deref())?;
            state.encoder = Some(encoder);
        }
        let encoder = state.encoder.as_mut().expect("started above");
        if (size, alpha) != (encoder.size, encoder.alpha) {
            return Err(Error::output(
                &self.path,
                frame,
                format!(
                    "a {}x{} frame{} in a movie of {}x{}{}: a movie's frames are all alike",
                    size.0,
                    size.1,
                    if alpha { " with alpha" } else { "" },
                    encoder.size.0,
                    encoder.size.1,
                    if encoder.alpha { " with alpha" } else { "" },
                ),
            ));
        }
        while let Some(strip) = next()? {
            let written = match strip.samples {
                Samples::U8(bytes) => encoder.write(&bytes),
                Samples::U16(samples) => {
                    let bytes: Vec<u8> = samples.iter().flat_map(|s| s.to_le_bytes()).collect();
                    encoder.write(&bytes)
                }
                Samples::F32(_) | Samples::Packed(_) => {
                    return Err(Error::internal("float or packed samples for a movie"))
                }
            };
            if written.is_err() {
                // ffmpeg has stopped: its own message says why.
                let message = encoder
                    .end()
                    .err()
                    .unwrap_or_else(|| "ffmpeg stopped".into());
                return Err(Error::output(&self.path, frame, message));
            }
        }
        Ok(())
    }

    /// Ends the movie: ffmpeg finishes it, and it is renamed into place.
    pub fn finish(&self) -> Result<()> {
        let Some(mut encoder) = self.lock().encoder.take() else {
            return Ok(());
        };
        let fail = |e: &dyn std::fmt::Display| Error::output(&self.path, None, e);
        encoder.end().map_err(|e| fail(&e))?;
        encoder.file.sync_all().map_err(|e| fail(&e))?;
        std::fs::rename(&encoder.temporary, &self.path)
            .map_err(|e| fail(&format!("cannot rename into place: {e}")))?;
        encoder.placed = true;
        Ok(())
    }

    /// Abandons the movie: ffmpeg is killed and the temporary removed.
    pub fn abort(&self) {
        drop(self.lock().encoder.take());
    }

    /// Starts ffmpeg writing the movie's temporary file.
    fn start(
        &self,
        size: (usize, usize),
        alpha: bool,
        rate: Rational,
        timecode: Option<&str>,
    ) -> Result<Encoder> {
        let fail = |e: &dyn std::fmt::Display| Error::output(&self.path, None, e);
        if let Some(dir) = self.path.parent().filter(|d| !d.as_os_str().is_empty()) {
            std::fs::create_dir_all(dir)
                .map_err(|e| fail(&format!("cannot create folder: {e}")))?;
        }
        let temporary = super::writer::temporary_path(&self.path);
        let file = super::writer::create_locked(&temporary)
            .map_err(|e| fail(&format!("cannot create: {e}")))?;
        let arguments = arguments(self.codec, self.container, size, alpha, rate, timecode);
        let mut command = Command::new(&self.ffmpeg);
        command
            .args(arguments)
            .arg(&temporary)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        // Its own process group: a Ctrl-C at the terminal reaches exrcomp
        // alone, which kills ffmpeg itself.
        std::os::unix::process::CommandExt::process_group(&mut command, 0);
        let mut encoder = Encoder {
            child: None,
            stdin: None,
            stderr: None,
            temporary,
            file,
            size,
            alpha,
            placed: false,
        };
        let mut child = command
            .spawn()
            .map_err(|e| fail(&format!("cannot start ffmpeg: {e}")))?;
        encoder.stdin = child
            .stdin
            .take()
            .map(|s| BufWriter::with_capacity(1 << 20, s));
        encoder.stderr = child.stderr.take().map(|mut stderr| {
            std::thread::spawn(move || {
                let mut text = String::new();
                let _ = stderr.read_to_string(&mut text);
                text
            })
        });
        encoder.child = Some(child);
        Ok(encoder)
    }
}

/// `code` one frame earlier at `rate` (a slate's); none where the rate has
/// no timecode counting.
fn earlier(code: &TimeCode, rate: Rational) -> Option<TimeCode> {
    let counting = super::timecode::Counting::new(rate, code.drop_frame).ok()?;
    counting.shift(code, -1).ok()
}

/// ffmpeg's arguments up to its output file: raw RGB frames on standard
/// input, converted to the codec's Y'CbCr with Rec. 709's matrix (limited
/// range) and tagged BT.709 (primaries, transfer, matrix); no metadata, no
/// creation time, bit-exact, so that the same frames make the same bytes.
fn arguments(
    codec: Codec,
    container: &str,
    (width, height): (usize, usize),
    alpha: bool,
    rate: Rational,
    timecode: Option<&str>,
) -> Vec<String> {
    let input = match (codec.bits(), alpha) {
        (Bits::Eight, false) => "rgb24",
        (Bits::Eight, true) => "rgba",
        (_, false) => "rgb48le",
        (_, true) => "rgba64le",
    };
    let (format, across, down) = codec.pixel_format(alpha);
    // Halved chroma needs even sides: an odd one gets a black column or row.
    let pad = match (across && width % 2 == 1, down && height % 2 == 1) {
        (false, false) => String::new(),
        (x, y) => format!("pad={}:{},", width + x as usize, height + y as usize),
    };
    let tags = "color_primaries=bt709:color_trc=bt709:colorspace=bt709:range=tv";
    // Chroma filtered from every pixel (full_chroma_inp, not averaged in
    // pairs), rounded exactly, and the same on every CPU (bitexact).
    let filter = format!(
        "{pad}scale=out_color_matrix=bt709:out_range=tv:\
         flags=accurate_rnd+full_chroma_int+full_chroma_inp+bitexact,\
         format={format},setparams={tags}"
    );
    let mut args: Vec<String> = [
        "-hide_banner",
        "-nostats",
        "-loglevel",
        "error",
        "-f",
        "rawvideo",
        "-pix_fmt",
        input,
        "-s",
        &format!("{width}x{height}"),
        "-framerate",
        &format!("{}/{}", rate.0, rate.1),
        "-i",
        "pipe:0",
        "-vf",
        &filter,
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    args.extend(codec.encoder().iter().map(|s| s.to_string()));
    let fixed = [
        "-color_primaries",
        "bt709",
        "-color_trc",
        "bt709",
        "-colorspace",
        "bt709",
        "-color_range",
        "tv",
        "-map_metadata",
        "-1",
        "-fflags",
        "+bitexact",
        "-flags:v",
        "+bitexact",
    ];
    args.extend(fixed.iter().map(|s| s.to_string()));
    if let Some(code) = timecode {
        args.extend(["-timecode".to_string(), code.to_string()]);
    }
    args.extend(["-f", container, "-y"].map(str::to_string));
    args
}

/// A running ffmpeg and the temporary file it writes: killed and removed
/// when dropped before the movie is placed.
struct Encoder {
    child: Option<Child>,
    stdin: Option<BufWriter<ChildStdin>>,
    stderr: Option<std::thread::JoinHandle<String>>,
    temporary: PathBuf,
    /// The temporary, open and locked (`writer::create_locked`) so that no
    /// other run's clean-up takes it while ffmpeg writes.
    file: File,
    size: (usize, usize),
    alpha: bool,
    placed: bool,
}

impl Encoder {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<()> {
        match &mut self.stdin {
            Some(stdin) => stdin.write_all(bytes),
            None => Err(std::io::Error::other("ffmpeg's input is closed")),
        }
    }

    /// Closes ffmpeg's input and waits for it: its first error line when it
    /// did not exit 0.
    fn end(&mut self) -> std::result::Result<(), String> {
        let flushed = self.stdin.take().map(|mut s| s.flush());
        let status = match self.child.take() {
            Some(mut child) => child.wait().map_err(|e| e.to_string())?,
            None => return Err("ffmpeg stopped".into()),
        };
        let text = self.stderr.take().and_then(|t| t.join().ok());
        let first = text
            .as_deref()
            .and_then(|t| t.lines().find(|l| !l.trim().is_empty()));
        match (status.success(), flushed) {
            (true, None | Some(Ok(()))) => Ok(()),
            _ => Err(format!(
                "ffmpeg failed ({status}): {}",
                first.unwrap_or("no message").trim()
            )),
        }
    }
}

impl Drop for Encoder {
    fn drop(&mut self) {
        if let Some(mut child) = self.child.take() {
            let _ = child.kill();
            let _ = child.wait();
        }
        if !self.placed {
            let _ = std::fs::remove_file(&self.temporary);
        }
    }
}

/// The executable `name` in one of PATH's folders.
fn on_path(name: &str) -> Option<PathBuf> {
    use std::os::unix::fs::PermissionsExt;
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|dir| dir.join(name))
        .find(|file| {
            std::fs::metadata(file)
                .is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odd_sides_are_padded_where_chroma_is_halved() {
        let args = |codec, size| arguments(codec, "mov", size, false, (24, 1), None).join(" ");
        assert!(args(Codec::H264, (63, 47)).contains("pad=64:48,"));
        assert!(args(Codec::Prores, (63, 47)).contains("pad=64:47,"));
        assert!(!args(Codec::Prores4444, (63, 47)).contains("pad="));
        assert!(!args(Codec::H264, (64, 48)).contains("pad="));
    }

    #[test]
    fn movies_are_fed_16_bits_for_10_bit_codecs() {
        let args = arguments(
            Codec::Prores,
            "mov",
            (8, 8),
            false,
            (24, 1),
            Some("01:00:00:00"),
        );
        let text = args.join(" ");
        assert!(text.contains("-pix_fmt rgb48le"));
        assert!(text.contains("-timecode 01:00:00:00"));
        assert!(text.contains("format=yuv422p10le"));
        let dnxhr = arguments(Codec::Dnxhr, "mov", (256, 144), false, (24, 1), None).join(" ");
        assert!(dnxhr.contains("-pix_fmt rgb48le"));
        assert!(dnxhr.contains("format=yuv444p10le"));
        assert!(dnxhr.contains("dnxhr_444"));
    }
}
