pub mod assess;
pub mod contact;
pub mod field;
pub mod solution;
pub mod stress;
