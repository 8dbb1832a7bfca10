//! Files and text at the edges of the program: bounded reading of what users give
//! ([`input`], and the probe's points, [`points`]) and of archive members and NumPy arrays
//! ([`archive`]), atomic writing ([`output`]), rows that sample a grid ([`grid_table`]), and
//! numbers and echoes for messages ([`text`]). Uses nothing else of the crate.

pub mod archive;
pub mod grid_table;
pub mod input;
pub mod output;
pub mod points;
pub mod text;
pub mod units;
