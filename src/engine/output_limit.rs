//! The most pixels an output frame may have, so that a typo (`resize --size
//! 100000x100000`, `--scale 1000`, `transform --skew 100,100`) is refused at
//! planning, with the size it would have, before it fills a volume
//! (specs/overnight.md, "Refused before any work").

use exr::meta::attribute::IntegerBounds;

/// How many times the largest input's pixels an output may have by
/// default: far above a real enlargement (a 2K plate to 16K is 64x).
pub const ENLARGEMENT: u64 = 64;

/// The default never falls under a 4096 x 4096 square: a small input (a
/// thumbnail, a one-pixel element) may still be made into a 4K plate, and
/// a typo on one writes at most that (256 MiB of float RGBA) a frame.
pub const FLOOR: u64 = 4096 * 4096;

/// The limit on an output's pixels: `asked` (`--max-output-pixels`), else
/// `ENLARGEMENT` times `largest` (the largest input's data or display
/// window, in pixels), at least `FLOOR`; none for a generated image (no
/// input: its size is asked outright).
pub fn limit(asked: Option<u64>, largest: Option<u64>) -> Option<u64> {
    asked.or_else(|| largest.map(|p| p.saturating_mul(ENLARGEMENT).max(FLOOR)))
}

/// Why `window` (an output frame's) is refused, when it has more pixels
/// than `limit` allows: its size and the limit. (`plan` leaves inputs so
/// far apart that they span it to its other limits, which name them.)
pub fn check(asked: Option<u64>, largest: Option<u64>, window: IntegerBounds) -> Option<String> {
    let limit = limit(asked, largest)?;
    let (width, height) = (window.size.width() as u64, window.size.height() as u64);
    let pixels = width.saturating_mul(height);
    if pixels <= limit {
        return None;
    }
    let rule = match asked {
        Some(_) => "--max-output-pixels".to_string(),
        None => format!(
            "{ENLARGEMENT} times the largest input's {} pixels, at least {FLOOR}",
            largest.unwrap_or(0)
        ),
    };
    Some(format!(
        "the result's data window would be {width} x {height} pixels ({pixels}), over the \
         limit of {limit} ({rule}): check the size asked, or give --max-output-pixels N to allow it"
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_limit_is_64_times_the_largest_input_at_least_a_4k_square() {
        assert_eq!(limit(None, Some(1920 * 1080)), Some(64 * 1920 * 1080));
        assert_eq!(limit(None, Some(64 * 64)), Some(FLOOR));
        assert_eq!(limit(None, Some(8192 * 8192)), Some(64 * 8192 * 8192));
        assert_eq!(limit(None, Some(u64::MAX)), Some(u64::MAX));
        assert_eq!(limit(Some(10), Some(8192 * 8192)), Some(10));
        assert_eq!(limit(None, None), None);
        let window = |w: usize, h: usize| IntegerBounds::new((0, 0), (w, h));
        assert!(check(None, Some(64 * 64), window(4096, 4096)).is_none());
        assert!(check(None, Some(64 * 64), window(4096, 4097)).is_some());
        let refused = check(None, Some(64 * 64), window(100_000, 100_000)).unwrap();
        assert!(refused.contains("would be 100000 x 100000 pixels (10000000000)"));
        assert!(check(Some(100), None, window(10, 11)).is_some());
        assert!(check(None, None, window(100_000, 100_000)).is_none());
    }
}
