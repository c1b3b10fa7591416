//! Drawing text into pixels: the font, used by burn-ins, the slate, the
//! demo's contact sheet and the bench chart.

pub mod font;
