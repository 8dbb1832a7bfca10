//! # stressfield
//!
//! Elastic stress fields under loaded contacts, from exact closed forms, evaluated in parallel
//! on grids and drawn as figures.
//!
//! ## Pipeline
//! Data flows one way, and the modules follow it:
//!
//! ```text
//! scene (what the user wrote) -> study (what will be computed) -> field (grids, rayon)
//!       -> sinks: figure + render (pixels / SVG), record (Rerun), report -> output
//! ```
//!
//! - [`scene`]: the file format only: `scenes/*.toml` parsed with serde (unknown keys rejected
//!   by dotted path) and validated, one file per table (`scene/validate/`), into plain typed
//!   values in SI units.
//! - [`study`]: a validated scene -> what is computed, once for every sink: whether it can be
//!   computed here (`study::admit`), the stress [`solution`] of each panel and its evaluated
//!   grid plane, the display units, the scene at each step of a sweep, the solved rough
//!   contact with its maxima and area curve, a surface's characterisation, the heating.
//! - [`contact`]: Hertz theory (effective modulus and radius, half-width, peak and mean
//!   pressure), materials, spur-gear geometry, elliptical contacts, partial slip.
//! - [`solution`]: stress solutions as pure functions of a point, in units of `a` and `p0`.
//! - [`stress`]: the stress tensor and derived measures (principal, von Mises, Tresca, τ1).
//! - [`surface`]: height maps of rough surfaces.
//! - [`lubrication`]: lubricated contacts: viscosity and density laws, the film-thickness
//!   regressions and λ, the numerical EHL solution of a line contact.
//! - [`field`]: grids, and the one place where rayon evaluates them.
//! - [`operator`]: below both contact and solution: the shared parallel 2-D FFT and the
//!   elastic half-space's surface-displacement operator.
//! - [`figure`]: the study's results in display units, laid out as figures and sheets; it
//!   never solves or evaluates.
//! - [`render`]: the drawing toolkit below the sinks: maps, contours, colour maps, charts and
//!   tables to pixels or SVG; knows no contact, does no I/O (scenes name its colour maps).
//! - [`report`]: the `hertz`, rough contact, surface and heating reports and the probe's CSV
//!   (the stress maxima and yield assessment they state are the study's, `study::assess`).
//! - [`io`]: reading user files within limits (and the probe's points), atomic writes, grid
//!   tables, numbers and echoes for messages.
//! - [`regression`]: comparison of images and fields with references, field files, the HTML
//!   report.
//!
//! The `stressfield` binary's command line (`src/cli/`: arguments, one module per subcommand,
//! console helpers) sits on top and is not part of the library.
//!
//! ## Conventions
//! - z >= 0 points into the body; depth is drawn downwards.
//! - Tension positive, compression negative; the pressure `p >= 0` pushes on the surface, so
//!   `σzz(x, 0) = -p(x)` inside the contact.
//! - The tangential traction `q = μ p` acts on the body's surface in +x, so `τxz(x, 0) = -q(x)`;
//!   the trailing edge is `x = -a`, where `σxx = +2 μ p0`.
//! - SI units internally; solutions work in units of the half-width `a` and peak pressure `p0`.

pub mod coating;
pub mod contact;
pub mod field;
pub mod figure;
pub mod io;
pub mod lubrication;
pub mod operator;
pub mod plasticity;
#[cfg(feature = "rerun")]
pub mod record;
pub mod regression;
pub mod render;
pub mod report;
pub mod scene;
pub mod solution;
pub mod stress;
pub mod study;
pub mod surface;
pub mod thermal;
pub mod wear;
