pub mod solution;
pub mod stress;
