//! A band of whole rows of one image: one typed plane per channel.

use super::text::Utf8Text;
use crate::stage_time::{self, Stage};
use exr::meta::attribute::{ChannelDescription, IntegerBounds, SampleType};
use half::f16;
use half::slice::HalfFloatSliceExt;
use rayon::prelude::*;
use std::mem::MaybeUninit;
use std::ops::Range;

/// Samples below which zeroing is not worth a task of its own.
const MIN_ZERO_PIECE: usize = 16 << 10;

/// Samples of one channel, row-major, in the channel's own type so that
/// pass-through channels stay bit-exact.
#[derive(Clone, Debug, PartialEq)]
pub enum Samples {
    F16(Vec<f16>),
    F32(Vec<f32>),
    U32(Vec<u32>),
}

impl Samples {
    pub fn zeros(kind: SampleType, len: usize) -> Self {
        match kind {
            SampleType::F16 => Samples::F16(vec![f16::ZERO; len]),
            SampleType::F32 => Samples::F32(vec![0.0; len]),
            SampleType::U32 => Samples::U32(vec![0; len]),
        }
    }

    /// Room for `len` samples, none of them set yet (see `unset_bytes`).
    pub fn with_capacity(kind: SampleType, len: usize) -> Self {
        match kind {
            SampleType::F16 => Samples::F16(Vec::with_capacity(len)),
            SampleType::F32 => Samples::F32(Vec::with_capacity(len)),
            SampleType::U32 => Samples::U32(Vec::with_capacity(len)),
        }
    }

    /// The bytes of the room beyond the samples set, to be written.
    pub fn unset_bytes(&mut self) -> &mut [MaybeUninit<u8>] {
        fn bytes<T>(v: &mut Vec<T>) -> &mut [MaybeUninit<u8>] {
            let spare = v.spare_capacity_mut();
            let len = std::mem::size_of_val(spare);
            // SAFETY: the same memory seen as bytes; any byte pattern may be
            // written to it, and MaybeUninit<u8> has alignment 1.
            unsafe { std::slice::from_raw_parts_mut(spare.as_mut_ptr().cast(), len) }
        }
        match self {
            Samples::F16(v) => bytes(v),
            Samples::F32(v) => bytes(v),
            Samples::U32(v) => bytes(v),
        }
    }

    /// Marks the first `len` samples of the room as set.
    ///
    /// # Safety
    /// All their bytes must have been written through `unset_bytes`.
    pub unsafe fn set_len(&mut self, len: usize) {
        match self {
            Samples::F16(v) => v.set_len(len),
            Samples::F32(v) => v.set_len(len),
            Samples::U32(v) => v.set_len(len),
        }
    }

    pub fn kind(&self) -> SampleType {
        match self {
            Samples::F16(_) => SampleType::F16,
            Samples::F32(_) => SampleType::F32,
            Samples::U32(_) => SampleType::U32,
        }
    }

    /// Converts `range` to f32 into `out`.
    pub fn read_f32(&self, range: Range<usize>, out: &mut [f32]) {
        match self {
            Samples::F16(v) => {
                v[range.clone()].convert_to_f32_slice(out);
                keep_nan_payloads_up(&v[range], out);
            }
            Samples::F32(v) => out.copy_from_slice(&v[range]),
            Samples::U32(v) => out
                .iter_mut()
                .zip(&v[range])
                .for_each(|(o, &s)| *o = s as f32),
        }
    }

    /// Stores f32 values into `range`, rounding to the plane's type
    /// (half: round to nearest even; u32: saturating, NaN to 0).
    pub fn write_f32(&mut self, range: Range<usize>, values: &[f32]) {
        self.as_mut().write_f32(range, values)
    }

    /// The native-endian bytes of `range`.
    pub fn bytes(&self, range: Range<usize>) -> &[u8] {
        match self {
            Samples::F16(v) => bytemuck::cast_slice(&v[range]),
            Samples::F32(v) => bytemuck::cast_slice(&v[range]),
            Samples::U32(v) => bytemuck::cast_slice(&v[range]),
        }
    }

    pub fn bytes_mut(&mut self, range: Range<usize>) -> &mut [u8] {
        self.as_mut().into_bytes(range)
    }

    /// The samples as a plane that can be split.
    pub fn as_mut(&mut self) -> PlaneMut<'_> {
        match self {
            Samples::F16(v) => PlaneMut::F16(v),
            Samples::F32(v) => PlaneMut::F32(v),
            Samples::U32(v) => PlaneMut::U32(v),
        }
    }

    /// How many samples it has room for without moving.
    fn capacity(&self) -> usize {
        match self {
            Samples::F16(v) => v.capacity(),
            Samples::F32(v) => v.capacity(),
            Samples::U32(v) => v.capacity(),
        }
    }

    /// Room for `len` samples in all, exactly (none if it has it).
    fn reserve_total(&mut self, len: usize) {
        fn exact<T>(v: &mut Vec<T>, len: usize) {
            v.reserve_exact(len.saturating_sub(v.len()));
        }
        match self {
            Samples::F16(v) => exact(v, len),
            Samples::F32(v) => exact(v, len),
            Samples::U32(v) => exact(v, len),
        }
    }

    /// Appends `count` zero samples, written in pieces on the pool (as
    /// compose's tasks, the only caller's): a strip's zeros are megabytes,
    /// which the compose thread would otherwise write alone.
    fn grow(&mut self, count: usize) {
        fn zeros<T: Copy + Send + Sync>(v: &mut Vec<T>, count: usize, zero: T) {
            v.reserve(count);
            let piece = count
                .div_ceil(4 * rayon::current_num_threads())
                .max(MIN_ZERO_PIECE);
            v.spare_capacity_mut()[..count]
                .par_chunks_mut(piece)
                .for_each(stage_time::tasks(
                    Stage::Compose,
                    |piece: &mut [MaybeUninit<T>]| piece.fill(MaybeUninit::new(zero)),
                ));
            // SAFETY: the first `count` samples of the spare room were just written.
            unsafe { v.set_len(v.len() + count) };
        }
        match self {
            Samples::F16(v) => zeros(v, count, f16::ZERO),
            Samples::F32(v) => zeros(v, count, 0.0),
            Samples::U32(v) => zeros(v, count, 0),
        }
    }

    /// Appends the samples of `other`, which must be of the same type.
    fn extend(&mut self, other: &Samples) {
        match (self, other) {
            (Samples::F16(a), Samples::F16(b)) => a.extend_from_slice(b),
            (Samples::F32(a), Samples::F32(b)) => a.extend_from_slice(b),
            (Samples::U32(a), Samples::U32(b)) => a.extend_from_slice(b),
            _ => panic!("appending planes of different sample types"),
        }
    }

    /// Puts the samples of `other`, of the same type, before its own.
    fn prepend(&mut self, other: &Samples) {
        fn before<T: Copy>(v: &mut Vec<T>, other: &[T]) {
            v.splice(0..0, other.iter().copied());
        }
        match (self, other) {
            (Samples::F16(a), Samples::F16(b)) => before(a, b),
            (Samples::F32(a), Samples::F32(b)) => before(a, b),
            (Samples::U32(a), Samples::U32(b)) => before(a, b),
            _ => panic!("prepending planes of different sample types"),
        }
    }

    /// Forgets the samples from `len` on.
    fn truncate(&mut self, len: usize) {
        match self {
            Samples::F16(v) => v.truncate(len),
            Samples::F32(v) => v.truncate(len),
            Samples::U32(v) => v.truncate(len),
        }
    }

    /// Forgets the first `count` samples; all of them frees the memory too
    /// (an emptied window takes over the next strip's planes as they are).
    fn drop_front(&mut self, count: usize) {
        fn drop_front<T>(v: &mut Vec<T>, count: usize) {
            if count >= v.len() {
                *v = Vec::new();
            } else {
                v.drain(..count);
            }
        }
        match self {
            Samples::F16(v) => drop_front(v, count),
            Samples::F32(v) => drop_front(v, count),
            Samples::U32(v) => drop_front(v, count),
        }
    }
}

/// Half NaNs as f32 NaNs with the same sign and payload, signalling ones
/// too: the half crate (and F16C) sets the quiet bit, which would rewrite
/// a signalling NaN that is only copied (merge's opaque over, a mix of 1).
fn keep_nan_payloads_up(halves: &[f16], out: &mut [f32]) {
    if !any_nan(halves) {
        return;
    }
    for (o, h) in out.iter_mut().zip(halves) {
        if h.is_nan() {
            let bits = h.to_bits() as u32;
            *o = f32::from_bits(((bits & 0x8000) << 16) | 0x7f80_0000 | ((bits & 0x3ff) << 13));
        }
    }
}

crate::simd::avx2_where_there! {
    /// Whether a half is NaN, in one pass that vectorises (a max over 16-bit
    /// lanes): NaNs are rare, and the payload fixes around it are scalar.
    fn any_nan(halves: &[f16]) -> bool {
        let magnitudes = halves.iter().map(|h| (h.to_bits() & 0x7fff) as i16);
        magnitudes.fold(0, i16::max) > 0x7c00
    }
}

/// The way back of `keep_nan_payloads_up`: an f32 NaN whose payload fits
/// in half's keeps it, quiet or signalling (one that does not stays a
/// quiet NaN, as the half crate makes it).
fn keep_nan_payloads_down(values: &[f32], out: &mut [f16]) {
    // The halves are NaN where the values are, and half as many bytes to scan.
    if !any_nan(out) {
        return;
    }
    for (o, v) in out.iter_mut().zip(values) {
        let bits = v.to_bits();
        if v.is_nan() && bits & 0x1fff == 0 {
            *o = f16::from_bits(
                (((bits >> 16) & 0x8000) | 0x7c00 | ((bits & 0x7f_ffff) >> 13)) as u16,
            );
        }
    }
}

/// A plane of samples borrowed to be written: a whole plane, or the rows of
/// one band of it.
pub enum PlaneMut<'a> {
    F16(&'a mut [f16]),
    F32(&'a mut [f32]),
    U32(&'a mut [u32]),
}

impl<'a> PlaneMut<'a> {
    /// Stores f32 values into `range`, rounding to the plane's type
    /// (half: round to nearest even; u32: saturating, NaN to 0).
    pub fn write_f32(&mut self, range: Range<usize>, values: &[f32]) {
        match self {
            PlaneMut::F16(v) => {
                v[range.clone()].convert_from_f32_slice(values);
                keep_nan_payloads_down(values, &mut v[range]);
            }
            PlaneMut::F32(v) => v[range].copy_from_slice(values),
            PlaneMut::U32(v) => v[range]
                .iter_mut()
                .zip(values)
                .for_each(|(o, &s)| *o = s as u32),
        }
    }

    pub fn bytes_mut(&mut self, range: Range<usize>) -> &mut [u8] {
        self.reborrow().into_bytes(range)
    }

    /// Sets each sample of `range` to `from`'s sample at the next index of
    /// `at`, bit for bit, or to zero where it has none: resampling by the
    /// nearest sample (transform, resize), which must not round through
    /// f32 (u32 ids past 2^24, NaN payloads, -0.0).
    pub fn gather(
        &mut self,
        range: Range<usize>,
        from: &Samples,
        at: impl IntoIterator<Item = Option<usize>>,
    ) {
        fn copy<T: Copy + Default>(
            to: &mut [T],
            from: &[T],
            at: impl Iterator<Item = Option<usize>>,
        ) {
            for (to, i) in to.iter_mut().zip(at) {
                *to = i.map_or_else(T::default, |i| from[i]);
            }
        }
        let at = at.into_iter();
        match (self, from) {
            (PlaneMut::F16(to), Samples::F16(from)) => copy(&mut to[range], from, at),
            (PlaneMut::F32(to), Samples::F32(from)) => copy(&mut to[range], from, at),
            (PlaneMut::U32(to), Samples::U32(from)) => copy(&mut to[range], from, at),
            _ => panic!("gathering samples of another type"),
        }
    }

    fn into_bytes(self, range: Range<usize>) -> &'a mut [u8] {
        match self {
            PlaneMut::F16(v) => bytemuck::cast_slice_mut(&mut v[range]),
            PlaneMut::F32(v) => bytemuck::cast_slice_mut(&mut v[range]),
            PlaneMut::U32(v) => bytemuck::cast_slice_mut(&mut v[range]),
        }
    }

    fn reborrow(&mut self) -> PlaneMut<'_> {
        match self {
            PlaneMut::F16(v) => PlaneMut::F16(v),
            PlaneMut::F32(v) => PlaneMut::F32(v),
            PlaneMut::U32(v) => PlaneMut::U32(v),
        }
    }

    /// The first `mid` samples and the rest.
    fn split_at(self, mid: usize) -> (Self, Self) {
        match self {
            PlaneMut::F16(v) => {
                let (a, b) = v.split_at_mut(mid);
                (PlaneMut::F16(a), PlaneMut::F16(b))
            }
            PlaneMut::F32(v) => {
                let (a, b) = v.split_at_mut(mid);
                (PlaneMut::F32(a), PlaneMut::F32(b))
            }
            PlaneMut::U32(v) => {
                let (a, b) = v.split_at_mut(mid);
                (PlaneMut::U32(a), PlaneMut::U32(b))
            }
        }
    }
}

/// Where rows `y .. y + height`, `width` pixels from column `x`, lie in an
/// image, and where the image has data: what owned rows and the bands
/// written in place share.
#[derive(Clone, Copy, Debug)]
pub struct Extent {
    pub x: i32,
    pub y: i32,
    pub width: usize,
    pub height: usize,
    /// Where the image has data; outside it every channel is transparent black
    /// (and alpha is 0 even when the image has no alpha channel).
    pub valid: IntegerBounds,
}

impl Extent {
    pub fn end(&self) -> i32 {
        self.y + self.height as i32
    }

    /// Sample index range of absolute row `y`.
    pub fn row_range(&self, y: i32) -> Range<usize> {
        debug_assert!(
            y >= self.y && y < self.end(),
            "row {y} outside {}..{}",
            self.y,
            self.end()
        );
        let start = (y - self.y) as usize * self.width;
        start..start + self.width
    }

    /// The alpha of an image without an alpha channel, for absolute row `y`
    /// from sample offset `from` on: 1 inside the valid window, 0 outside it.
    pub fn implicit_alpha(&self, y: i32, from: usize, out: &mut [f32]) {
        let v = self.valid;
        let inside_row = y >= v.position.y() && y < v.end().y();
        for (i, o) in out.iter_mut().enumerate() {
            let x = self.x + (from + i) as i32;
            let inside = inside_row && x >= v.position.x() && x < v.end().x();
            *o = if inside { 1.0 } else { 0.0 };
        }
    }

    /// The columns of the valid window, as sample offsets within a row.
    pub fn valid_columns(&self) -> Range<usize> {
        let start = (self.valid.position.x() - self.x).clamp(0, self.width as i32) as usize;
        let end = (self.valid.end().x() - self.x).clamp(0, self.width as i32) as usize;
        start..end.max(start)
    }

    /// The rows held that are inside the valid window (absolute).
    pub fn valid_rows(&self) -> Range<i32> {
        let start = self.y.max(self.valid.position.y());
        start..self.end().min(self.valid.end().y()).max(start)
    }

    /// Whether absolute row `y` is inside the valid window.
    pub fn valid_row(&self, y: i32) -> bool {
        y >= self.valid.position.y() && y < self.valid.end().y()
    }
}

/// Rows of an image, one typed plane per channel, each `width * height`
/// samples row-major.
#[derive(Clone, Debug)]
pub struct Rows {
    pub extent: Extent,
    pub channels: Vec<ChannelDescription>,
    pub planes: Vec<Samples>,
}

impl std::ops::Deref for Rows {
    type Target = Extent;
    fn deref(&self) -> &Extent {
        &self.extent
    }
}

impl std::ops::DerefMut for Rows {
    fn deref_mut(&mut self) -> &mut Extent {
        &mut self.extent
    }
}

/// A band of rows written in place: what an operation computes, while other
/// bands of the same rows are computed on other threads.
pub struct RowsMut<'a> {
    pub extent: Extent,
    pub channels: &'a [ChannelDescription],
    pub planes: Vec<PlaneMut<'a>>,
}

impl std::ops::Deref for RowsMut<'_> {
    type Target = Extent;
    fn deref(&self) -> &Extent {
        &self.extent
    }
}

impl RowsMut<'_> {
    pub fn channel_index(&self, name: &str) -> Option<usize> {
        channel_index(self.channels, name)
    }

    /// Copies absolute row `y` of every plane from `other`, which has the
    /// same channels and columns.
    pub fn copy_row_from(&mut self, other: &Rows, y: i32) {
        let range = self.extent.row_range(y);
        for (plane, source) in self.planes.iter_mut().zip(&other.planes) {
            plane
                .bytes_mut(range.clone())
                .copy_from_slice(source.bytes(other.row_range(y)));
        }
    }
}

fn channel_index(channels: &[ChannelDescription], name: &str) -> Option<usize> {
    channels.iter().position(|c| c.name.is(name))
}

impl Rows {
    pub fn zeros(
        x: i32,
        y: i32,
        width: usize,
        height: usize,
        channels: Vec<ChannelDescription>,
        valid: IntegerBounds,
    ) -> Self {
        let planes = channels
            .iter()
            .map(|c| Samples::zeros(c.sample_type, width * height))
            .collect();
        Rows {
            extent: Extent {
                x,
                y,
                width,
                height,
                valid,
            },
            channels,
            planes,
        }
    }

    pub fn channel_index(&self, name: &str) -> Option<usize> {
        channel_index(&self.channels, name)
    }

    /// Appends the rows of `below`, which must start at `self.end()` and have
    /// the same columns and channels.
    pub fn append(&mut self, below: Rows) {
        assert_eq!(below.y, self.end(), "rows must be appended in order");
        self.join(below, Samples::extend);
    }

    /// Puts the rows of `above`, which must end at `self.y` and have the
    /// same columns and channels, before its own (a zone read bottom-up).
    pub fn prepend(&mut self, above: Rows) {
        assert_eq!(above.end(), self.y, "rows must be prepended in order");
        self.extent.y = above.y;
        self.join(above, Samples::prepend);
    }

    /// Takes the rows of `other` into each plane by `add`.
    fn join(&mut self, other: Rows, add: fn(&mut Samples, &Samples)) {
        assert_eq!(other.width, self.width);
        // Empty, it takes the other's planes as they are, unless it has
        // made room (`reserve`) for more rows than they hold.
        let len = other.height * other.width;
        if self.height == 0 && self.planes.iter().any(|p| p.capacity() < len) {
            self.planes = other.planes;
        } else {
            for (plane, other) in self.planes.iter_mut().zip(&other.planes) {
                add(plane, other);
            }
        }
        self.extent.height += other.extent.height;
    }

    /// Room for `height` rows in all, so that growing to them moves no
    /// plane: a plane grown by moving holds its old buffer and a new one
    /// twice the size, the old left in the heap (`mallopt` in `cli/program.rs`).
    pub fn reserve(&mut self, height: usize) {
        for plane in &mut self.planes {
            plane.reserve_total(height * self.extent.width);
        }
    }

    /// Appends `height` rows of zeros, to be written in place (`bands`).
    pub fn grow(&mut self, height: usize) {
        for plane in &mut self.planes {
            plane.grow(height * self.extent.width);
        }
        self.extent.height += height;
    }

    /// Puts `height` rows of zeros before its own, to be written in place
    /// (`bands_in`).
    pub fn grow_up(&mut self, height: usize) {
        let above = Rows::zeros(
            self.x,
            self.y - height as i32,
            self.width,
            height,
            self.channels.clone(),
            self.valid,
        );
        self.prepend(above);
    }

    /// Rows `from ..` (absolute) cut into bands of `band` rows (the last
    /// one shorter), each writable on its own.
    pub fn bands(&mut self, from: i32, band: usize) -> Vec<RowsMut<'_>> {
        let end = self.extent.end();
        self.bands_in(from..end, band)
    }

    /// Rows `rows` (absolute) cut into bands of `band` rows, as `bands`.
    pub fn bands_in(&mut self, rows: Range<i32>, band: usize) -> Vec<RowsMut<'_>> {
        let from = rows.start;
        let skip = (from - self.extent.y) as usize * self.extent.width;
        let mut rest: Vec<PlaneMut> = self
            .planes
            .iter_mut()
            .map(|p| p.as_mut().split_at(skip).1)
            .collect();
        let mut bands = Vec::new();
        let mut y = from;
        while y < rows.end {
            let height = band.min((rows.end - y) as usize);
            let (now, later): (Vec<_>, Vec<_>) = rest
                .into_iter()
                .map(|p| p.split_at(height * self.extent.width))
                .unzip();
            rest = later;
            bands.push(RowsMut {
                extent: Extent {
                    y,
                    height,
                    ..self.extent
                },
                channels: &self.channels,
                planes: now,
            });
            y += height as i32;
        }
        bands
    }

    /// Forgets the rows above `y`.
    pub fn drop_rows_before(&mut self, y: i32) {
        let count = (y.clamp(self.y, self.end()) - self.y) as usize;
        if count == 0 {
            return;
        }
        for plane in &mut self.planes {
            plane.drop_front(count * self.extent.width);
        }
        self.y += count as i32;
        self.height -= count;
    }

    /// Forgets the rows from `y` on (a zone read bottom-up).
    pub fn drop_rows_from(&mut self, y: i32) {
        let keep = (y.clamp(self.y, self.end()) - self.y) as usize;
        for plane in &mut self.planes {
            plane.truncate(keep * self.extent.width);
        }
        self.height = keep;
    }

    /// Rows `range` (absolute): moved out when they are all the rows held
    /// (the window is then empty, starting at `range.end`), else copied.
    pub fn take_rows(&mut self, range: Range<i32>) -> Rows {
        if range.start == self.y && range.end == self.end() {
            let empty = Rows::zeros(
                self.x,
                range.end,
                self.width,
                0,
                self.channels.clone(),
                self.valid,
            );
            return std::mem::replace(self, empty);
        }
        self.copy_rows(range)
    }

    /// A copy of rows `range` (absolute).
    pub fn copy_rows(&self, range: Range<i32>) -> Rows {
        self.copy_region(range, self.x..self.x + self.width as i32)
    }

    /// A copy of rows `rows` and columns `columns` (absolute), which it holds.
    pub fn copy_region(&self, rows: Range<i32>, columns: Range<i32>) -> Rows {
        let width = (columns.end - columns.start) as usize;
        let skip = (columns.start - self.x) as usize;
        let height = (rows.end - rows.start) as usize;
        let planes = self
            .planes
            .iter()
            .map(|p| {
                let mut out = Samples::zeros(p.kind(), width * height);
                for (line, y) in rows.clone().enumerate() {
                    let from = self.row_range(y).start + skip;
                    out.bytes_mut(line * width..(line + 1) * width)
                        .copy_from_slice(p.bytes(from..from + width));
                }
                out
            })
            .collect();
        Rows {
            extent: Extent {
                x: columns.start,
                y: rows.start,
                width,
                height,
                ..self.extent
            },
            channels: self.channels.clone(),
            planes,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every half NaN, signalling or quiet, goes to f32 and back as it was.
    #[test]
    fn half_nans_keep_their_bits_through_f32() {
        let nans: Vec<f16> = (0..=u16::MAX)
            .map(f16::from_bits)
            .filter(|h| h.is_nan())
            .collect();
        assert_eq!(nans.len(), 2046);
        let plane = Samples::F16(nans.clone());
        let mut wide = vec![0.0; nans.len()];
        plane.read_f32(0..nans.len(), &mut wide);
        assert!(wide.iter().all(|v| v.is_nan()));
        let mut back = Samples::zeros(SampleType::F16, nans.len());
        back.write_f32(0..nans.len(), &wide);
        let n = nans.len();
        assert_eq!(back.bytes(0..n), plane.bytes(0..n));
    }
}
