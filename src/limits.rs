//! Limits that several layers keep: at the bottom of the pipeline, so that the input readers
//! (`io`) and the field evaluation (`field`) see the same number without one reaching up to
//! the other.

/// Largest grid (in bytes of stored values) that [`crate::field::evaluate`] accepts on any
/// machine; less when the machine has less memory available (see
/// [`crate::field::memory_limit_bytes`]). A regression run's reference file may hold a
/// quarter of it ([`crate::io::input::REFERENCE_FILE_LIMIT`]).
pub const MAX_FIELD_BYTES: usize = 4 << 30;
