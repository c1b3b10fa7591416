//! A 5x7 bitmap font for the contact sheet's labels, burn-ins and slates:
//! capitals, digits and a little punctuation (lower case is drawn as capitals), each glyph seven
//! rows of five pixels, `#` lit.

/// Glyph size in pixels, before scaling, and the advance between glyphs.
pub const WIDTH: usize = 5;
pub const HEIGHT: usize = 7;
pub const ADVANCE: usize = WIDTH + 1;

const GLYPHS: &[(char, &str)] = &[
    ('A', ".###.|#...#|#...#|#####|#...#|#...#|#...#"),
    ('B', "####.|#...#|#...#|####.|#...#|#...#|####."),
    ('C', ".###.|#...#|#....|#....|#....|#...#|.###."),
    ('D', "###..|#..#.|#...#|#...#|#...#|#..#.|###.."),
    ('E', "#####|#....|#....|####.|#....|#....|#####"),
    ('F', "#####|#....|#....|####.|#....|#....|#...."),
    ('G', ".###.|#...#|#....|#.###|#...#|#...#|.####"),
    ('H', "#...#|#...#|#...#|#####|#...#|#...#|#...#"),
    ('I', ".###.|..#..|..#..|..#..|..#..|..#..|.###."),
    ('J', "..###|...#.|...#.|...#.|...#.|#..#.|.##.."),
    ('K', "#...#|#..#.|#.#..|##...|#.#..|#..#.|#...#"),
    ('L', "#....|#....|#....|#....|#....|#....|#####"),
    ('M', "#...#|##.##|#.#.#|#.#.#|#...#|#...#|#...#"),
    ('N', "#...#|#...#|##..#|#.#.#|#..##|#...#|#...#"),
    ('O', ".###.|#...#|#...#|#...#|#...#|#...#|.###."),
    ('P', "####.|#...#|#...#|####.|#....|#....|#...."),
    ('Q', ".###.|#...#|#...#|#...#|#.#.#|#..#.|.##.#"),
    ('R', "####.|#...#|#...#|####.|#.#..|#..#.|#...#"),
    ('S', ".####|#....|#....|.###.|....#|....#|####."),
    ('T', "#####|..#..|..#..|..#..|..#..|..#..|..#.."),
    ('U', "#...#|#...#|#...#|#...#|#...#|#...#|.###."),
    ('V', "#...#|#...#|#...#|#...#|#...#|.#.#.|..#.."),
    ('W', "#...#|#...#|#...#|#.#.#|#.#.#|#.#.#|.#.#."),
    ('X', "#...#|#...#|.#.#.|..#..|.#.#.|#...#|#...#"),
    ('Y', "#...#|#...#|.#.#.|..#..|..#..|..#..|..#.."),
    ('Z', "#####|....#|...#.|..#..|.#...|#....|#####"),
    ('0', ".###.|#...#|#..##|#.#.#|##..#|#...#|.###."),
    ('1', "..#..|.##..|..#..|..#..|..#..|..#..|.###."),
    ('2', ".###.|#...#|....#|...#.|..#..|.#...|#####"),
    ('3', "#####|...#.|..#..|...#.|....#|#...#|.###."),
    ('4', "...#.|..##.|.#.#.|#..#.|#####|...#.|...#."),
    ('5', "#####|#....|####.|....#|....#|#...#|.###."),
    ('6', "..##.|.#...|#....|####.|#...#|#...#|.###."),
    ('7', "#####|....#|...#.|..#..|.#...|.#...|.#..."),
    ('8', ".###.|#...#|#...#|.###.|#...#|#...#|.###."),
    ('9', ".###.|#...#|#...#|.####|....#|...#.|.##.."),
    (' ', ".....|.....|.....|.....|.....|.....|....."),
    ('-', ".....|.....|.....|#####|.....|.....|....."),
    ('+', ".....|..#..|..#..|#####|..#..|..#..|....."),
    ('.', ".....|.....|.....|.....|.....|.##..|.##.."),
    (',', ".....|.....|.....|.....|.##..|..#..|.#..."),
    (':', ".....|.##..|.##..|.....|.##..|.##..|....."),
    ('/', ".....|....#|...#.|..#..|.#...|#....|....."),
    ('(', "...#.|..#..|.#...|.#...|.#...|..#..|...#."),
    (')', ".#...|..#..|...#.|...#.|...#.|..#..|.#..."),
    ('=', ".....|.....|#####|.....|#####|.....|....."),
    ('?', ".###.|#...#|....#|...#.|..#..|.....|..#.."),
    ('#', ".#.#.|.#.#.|#####|.#.#.|#####|.#.#.|.#.#."),
    ('_', ".....|.....|.....|.....|.....|.....|#####"),
];

/// Whether pixel (x, y) of `c`'s glyph is lit; a character the font lacks
/// is drawn as `?`.
pub fn lit(c: char, x: usize, y: usize) -> bool {
    let c = c.to_ascii_uppercase();
    let rows = GLYPHS
        .iter()
        .find(|(g, _)| *g == c)
        .or_else(|| GLYPHS.iter().find(|(g, _)| *g == '?'))
        .map(|(_, rows)| *rows)
        .expect("the font has '?'");
    rows.split('|')
        .nth(y)
        .and_then(|row| row.as_bytes().get(x))
        .is_some_and(|&b| b == b'#')
}

/// Whether pixel (x, y) of `text` drawn at `scale` (each font pixel a
/// square of that side), from its top left, is lit: the one way text is
/// drawn, by the burn-ins and slates a row at a time and through `pixels`.
pub fn lit_in(text: &[char], x: usize, y: usize, scale: usize) -> bool {
    let (gx, gy) = (x / scale, y / scale);
    gy < HEIGHT
        && text
            .get(gx / ADVANCE)
            .is_some_and(|&c| lit(c, gx % ADVANCE, gy))
}

/// The lit pixels of `text` drawn at `scale` (`lit_in`), from its top
/// left; how the chart and the contact sheet draw text.
pub fn pixels(text: &str, scale: usize) -> impl Iterator<Item = (usize, usize)> {
    let chars: Vec<char> = text.chars().collect();
    let (width, height) = (text_width(text) * scale, HEIGHT * scale);
    (0..height)
        .flat_map(move |y| (0..width).map(move |x| (x, y)))
        .filter(move |&(x, y)| lit_in(&chars, x, y, scale))
}

/// Width in pixels of `text` at scale 1.
pub fn text_width(text: &str) -> usize {
    (text.chars().count() * ADVANCE).saturating_sub(1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_glyph_is_seven_rows_of_five_and_distinct() {
        for (c, rows) in GLYPHS {
            let rows: Vec<&str> = rows.split('|').collect();
            assert_eq!(rows.len(), HEIGHT, "{c}");
            assert!(rows.iter().all(|r| r.len() == WIDTH), "{c}");
        }
        let mut bitmaps: Vec<&str> = GLYPHS.iter().map(|(_, r)| *r).collect();
        bitmaps.sort();
        bitmaps.dedup();
        assert_eq!(bitmaps.len(), GLYPHS.len(), "two glyphs are drawn alike");
    }

    #[test]
    fn lower_case_is_drawn_as_capitals_and_unknowns_as_a_question_mark() {
        let pixels = |c| -> Vec<bool> {
            (0..HEIGHT)
                .flat_map(|y| (0..WIDTH).map(move |x| lit(c, x, y)))
                .collect()
        };
        assert_eq!(pixels('a'), pixels('A'));
        assert_eq!(pixels('~'), pixels('?'));
        assert!(lit('L', 0, 0) && !lit('L', 4, 0) && lit('L', 4, 6));
        assert_eq!(text_width("AB"), 11);
    }
}
