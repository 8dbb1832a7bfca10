//! One integration-test binary, one module per topic (see STYLE.md: each test binary links the
//! whole crate, so keep them few).

mod cli;
mod contracts;
mod dcfft;
mod golden;
mod heating_agree;
mod inputs;
mod line_contact;
mod lubrication;
mod mutations;
mod patch;
mod plastic;
mod plastic_sheet;
mod point_contact;
#[cfg(feature = "rerun")]
mod record;
#[cfg(feature = "rerun")]
mod record_agree;
mod regression;
mod rough_capped;
mod rough_contact;
mod rough_sheet;
mod scenes;
mod surfaces;
mod thermal;
mod wear;
