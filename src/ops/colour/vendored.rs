//! Checks of exrcomp's changes to the vendored `ocio` crate
//! (vendor/ocio/patches/README.md), whose own tests do not build here.

use half::f16;
use ocio::ops::lut1d::half_domain_interpolations;

/// A half-domain 1D LUT's interpolation without half conversions gives the
/// exact one's bits: on every half and the f32 values around it (ties, one
/// and two ulps off), a sweep of all f32 patterns, and the edges (zeros,
/// HALF_MAX, values that round to infinity, infinities, NaN).
#[test]
fn fast_half_domain_interpolation_is_the_exact_one() {
    let lut: Vec<f32> = (0..65536)
        .map(|i| (i as f32 * 0.37).sin() * 1000.0)
        .collect();
    let mut values: Vec<f32> = (0..=u16::MAX)
        .flat_map(|h| {
            let f = f16::from_bits(h).to_f32().to_bits();
            [0, 1, 2, 0xfff, 0x1000, 0x1001]
                .into_iter()
                .flat_map(move |d: u32| [f.wrapping_add(d), f.wrapping_sub(d)])
        })
        .map(f32::from_bits)
        .collect();
    values.extend((0..u32::MAX / 4099).map(|i| f32::from_bits(i * 4099)));
    values.extend([0.0, -0.0, 65504.0, -65504.0, 65519.99, 65520.0, f32::MAX]);
    values.extend([
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        f32::MIN_POSITIVE,
    ]);
    let both = half_domain_interpolations(lut, &values);
    for (v, (fast, exact)) in values.iter().zip(both) {
        assert_eq!(
            fast.to_bits(),
            exact.to_bits(),
            "{v:e} ({:#x})",
            v.to_bits()
        );
    }
}
