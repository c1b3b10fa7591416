//! Where a flat part's blocks lie: its levels (one for scanline and
//! single-level tiled parts; mipmaps and ripmaps have more), each level's size
//! by OpenEXR's rounding rules, and which offset-table entries hold the
//! blocks of a level. A scanline part is read as one level of blocks as wide
//! as the data window and as tall as its compression's lines per block, so
//! one cursor reads both (`engine::decode`).

use exr::block::chunk::TileCoordinates;
use exr::math::Vec2;
use exr::meta::attribute::{IntegerBounds, LevelMode};
use exr::meta::header::Header;
use exr::meta::{compute_block_count, mip_map_levels, rip_map_levels, BlockDescription};

/// One level of a part and its blocks' place in the offset table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Level {
    /// The level's index (x, y): (0, 0) is the full resolution; a mipmap's
    /// level `n` is (n, n).
    pub index: Vec2<usize>,
    /// Its pixels, from the data window's origin.
    pub size: Vec2<usize>,
    /// The size of its blocks (the last column and row may be cut short).
    pub block: Vec2<usize>,
    /// Its blocks across and down.
    pub blocks: Vec2<usize>,
    /// The offset-table index of its first block; the others follow row by
    /// row, left to right.
    pub first: usize,
}

impl Level {
    /// The level's pixels placed at the part's data window origin (OpenEXR's
    /// `dataWindowForLevel`).
    pub fn window(&self, header: &Header) -> IntegerBounds {
        IntegerBounds::new(header.own_attributes.layer_position, self.size)
    }

    /// The offset-table index of block (`x`, `y`), counted in blocks.
    pub fn chunk(&self, x: usize, y: usize) -> usize {
        self.first + y * self.blocks.x() + x
    }

    fn count(&self) -> usize {
        self.blocks.area()
    }
}

/// The levels of `header`'s part in offset-table order: level 0's tiles, then
/// (mipmaps) level 1's and so on, or (ripmaps) every x level of y level 0,
/// then of y level 1...
pub fn levels(header: &Header) -> Vec<Level> {
    let size = header.layer_size;
    let block = header.max_block_pixel_size();
    let indices: Vec<(Vec2<usize>, Vec2<usize>)> = match header.blocks {
        BlockDescription::Tiles(tiles) if tiles.level_mode == LevelMode::MipMap => {
            mip_map_levels(tiles.rounding_mode, size)
                .map(|(n, size)| (Vec2(n, n), size))
                .collect()
        }
        BlockDescription::Tiles(tiles) if tiles.level_mode == LevelMode::RipMap => {
            rip_map_levels(tiles.rounding_mode, size).collect()
        }
        _ => vec![(Vec2(0, 0), size)],
    };
    let mut first = 0;
    indices
        .into_iter()
        .map(|(index, size)| {
            let level = Level {
                index,
                size,
                block,
                blocks: Vec2(
                    compute_block_count(size.width(), block.width()),
                    compute_block_count(size.height(), block.height()),
                ),
                first,
            };
            first += level.count();
            level
        })
        .collect()
}

/// The level `asked` of `header`'s part; `None` asks for level 0. A number
/// `n` alone (x = y) names mipmap level `n`, or ripmap level (`n`, `n`).
pub fn level(header: &Header, asked: Option<Vec2<usize>>) -> Result<Level, String> {
    let all = levels(header);
    let asked = asked.unwrap_or(Vec2(0, 0));
    if let Some(level) = all.iter().find(|l| l.index == asked) {
        return Ok(*level);
    }
    let last = all.last().expect("a part has a level").index;
    let kind = match header.blocks {
        BlockDescription::Tiles(t) if t.level_mode == LevelMode::MipMap => {
            format!("is mipmapped: levels 0 to {}", last.x())
        }
        BlockDescription::Tiles(t) if t.level_mode == LevelMode::RipMap => {
            format!("is ripmapped: levels 0,0 to {},{}", last.x(), last.y())
        }
        _ => "has one level only (0)".to_string(),
    };
    Err(format!("has no level {}: it {kind}", name(asked)))
}

/// A level as `--level` takes it: `n` for (n, n), else `x,y`.
pub fn name(level: Vec2<usize>) -> String {
    match level {
        Vec2(x, y) if x == y => format!("{x}"),
        Vec2(x, y) => format!("{x},{y}"),
    }
}

/// The block that offset-table entry `index` of `header`'s part must hold.
pub fn block_at(header: &Header, index: usize) -> Option<TileCoordinates> {
    let level = levels(header)
        .into_iter()
        .find(|l| (l.first..l.first + l.count()).contains(&index))?;
    let k = index - level.first;
    Some(TileCoordinates {
        tile_index: Vec2(k % level.blocks.x(), k / level.blocks.x()),
        level_index: level.index,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use exr::math::RoundingMode;
    use exr::meta::attribute::TileDescription;
    use exr::prelude::Compression;

    fn tiled(size: (usize, usize), tile: usize, mode: LevelMode, round: RoundingMode) -> Header {
        Header::new("image".into(), size, Default::default()).with_encoding(
            Compression::ZIP1,
            BlockDescription::Tiles(TileDescription {
                tile_size: Vec2(tile, tile),
                level_mode: mode,
                rounding_mode: round,
            }),
            exr::meta::attribute::LineOrder::Increasing,
        )
    }

    #[test]
    fn mipmap_levels_round_as_the_tile_description_says() {
        let down = levels(&tiled((97, 61), 32, LevelMode::MipMap, RoundingMode::Down));
        let sizes: Vec<_> = down.iter().map(|l| (l.size.x(), l.size.y())).collect();
        assert_eq!(
            sizes,
            [
                (97, 61),
                (48, 30),
                (24, 15),
                (12, 7),
                (6, 3),
                (3, 1),
                (1, 1)
            ]
        );
        let up = levels(&tiled((97, 61), 32, LevelMode::MipMap, RoundingMode::Up));
        let sizes: Vec<_> = up.iter().map(|l| (l.size.x(), l.size.y())).collect();
        assert_eq!(
            sizes,
            [
                (97, 61),
                (49, 31),
                (25, 16),
                (13, 8),
                (7, 4),
                (4, 2),
                (2, 1),
                (1, 1)
            ]
        );
        // 4 x 2 tiles of level 0, then 2 x 1 of level 1...
        assert_eq!((down[1].first, down[1].blocks), (8, Vec2(2, 1)));
        assert_eq!((down[2].first, down[2].blocks), (10, Vec2(1, 1)));
        let header = tiled((97, 61), 32, LevelMode::MipMap, RoundingMode::Down);
        let total: usize = down.iter().map(Level::count).sum();
        assert_eq!(total, header.chunk_count);
        let at = block_at(&header, 9).unwrap();
        assert_eq!((at.tile_index, at.level_index), (Vec2(1, 0), Vec2(1, 1)));
    }

    #[test]
    fn ripmap_levels_go_x_first() {
        let header = tiled((64, 32), 16, LevelMode::RipMap, RoundingMode::Down);
        let all = levels(&header);
        let indices: Vec<_> = all.iter().map(|l| (l.index.x(), l.index.y())).collect();
        assert_eq!(
            &indices[..8],
            [
                (0, 0),
                (1, 0),
                (2, 0),
                (3, 0),
                (4, 0),
                (5, 0),
                (6, 0),
                (0, 1)
            ]
        );
        assert_eq!(
            all.iter().map(Level::count).sum::<usize>(),
            header.chunk_count
        );
        assert_eq!(level(&header, Some(Vec2(2, 1))).unwrap().size, Vec2(16, 16));
        assert!(level(&header, Some(Vec2(7, 0))).is_err());
    }
}
