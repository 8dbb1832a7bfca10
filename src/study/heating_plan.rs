//! What the heating of a scene (`[thermal]`) will cost, planned before anything is computed:
//! the grid its study takes, the memory and the CPU time, and whether that grid resolves the
//! speeds. [`crate::study::admit`] refuses a scene beyond these limits (so `check` does), naming
//! the key the scene wrote: the speed that sets a Hertz contact's grid, the size of a rough
//! scene's map, the pinion's speed of running gears (issue 42, classes 2 and 4).
//!
//! ## The cost, measured
//! A 3-D heating study keeps the thermal stress operator of one depth at a time: what its six
//! influence-coefficient lattices of `2ny x 2nx` are built from (the smooth part's samples, on a
//! lattice up to four times longer in x), one lattice and its spectrum at a time (issue 41),
//! besides the contact's DC-FFT layers and the thermal layers kept for the interpolation in
//! depth. Measured with
//! `/usr/bin/time -v` on `stressfield thermal` (release build, 2026-11-27, two cores shared with
//! another build: CPU time is the sum over threads):
//!
//! | grid | cells | peak memory | CPU time |
//! |---|---|---|---|
//! | rough ball, 64² | 4 096 | 14.9 MB | 2.9 s |
//! | rough ball, 128² | 16 384 | 35.3 MB | 9.1 s |
//! | rough ball, 256² | 65 536 | 108 MB | 34 s |
//! | rough ball, 384² | 147 456 | 232 MB | 74 s |
//! | rough ball, 512² | 262 144 | 408 MB | 108 s |
//! | sliding sphere at 2 m/s (Pe 32), 129 x 97 | 12 513 | 26.4 MB | 8.1 s |
//! | the same at 6.25 m/s (Pe 100), 403 x 303 | 122 109 | 188 MB | 61 s |
//! | the same at 9 m/s (Pe 144), 580 x 436 | 252 880 | 381 MB | 112 s |
//!
//! so about 1.5 kB and 0.5 ms of CPU a cell; since the maxima are refined (issue 38, about 40
//! layers instead of 16) 1.2 ms a cell ([`BYTES_PER_CELL`], [`CPU_SECONDS_PER_CELL`]);
//! the heating sheet (`--figure`, `render`) evaluates 25 more depths (19 s in all for the
//! sphere at 2 m/s). A line contact's plane problem is a row of at most 640 strips: its grid
//! is small (the gears' 41 points of the path and the study at the hottest: 0.1 s).
//!
//! ## The limits
//! - A Hertz contact's 3-D heating grid of at most [`MAX_CELLS`] cells (512 x 512): its grid is
//!   refined with the speed (cells of `1/u` below `a/20`), so this bounds the Péclet number
//!   (about 148 for a sphere).
//! - A rough map's heating of at most [`ROUGH_MAX_CELLS`] cells (2048 x 2048), the grid being
//!   the map's, within the same memory limit as its contact (issue 41): measured
//!   (`/usr/bin/time -v`, 2026-11-28, issue 41's scenes) 2.0 to 2.4 times `contact`'s peak from
//!   256² to 2048² (2048² periodic: 3483 MiB against 1585 MiB), 1.75 to 2.13 times from 256² to
//!   2048² since the thermal stress operator holds one lattice at a time (2048² periodic:
//!   3024 MiB), so
//!   [`ROUGH_HEATING_BYTES_PER_CELL`] and [`CONTACT_BYTES_PER_CELL`] ([`contact_cost`], which
//!   `check` states for a rough scene without heating too).
//! - Memory within [`crate::field::memory_limit_bytes`].
//! - The cell Péclet number `u dx` within [`MAX_CELL_PECLET`] (a Hertz grid of at most 640
//!   cells across `4a`; a rough map as sampled; gears at every point of the path).

use crate::field::memory_limit_bytes;
use crate::scene::{ContactKind, Scene, ThermalSpec};
use crate::study::gear_heating::{path_positions, scene_at};
use crate::study::thermal::{hertz_layout, inverse_length, ThermalStudyError, STUDY_WINDOW};
use crate::thermal::temperature::MAX_CELL_PECLET;

/// Peak memory of a 3-D heating study of a Hertz contact a cell of its grid (measured before
/// issue 41: 1.47 to 1.54 kB; since its thermal stress keeps no kernel spectra and its layers
/// are computed two depths at a time, 1.65 kB on the sliding sphere at 9 m/s, 580 x 437
/// cells: 415 MiB against the 403 MiB this estimates, measured 2026-11-28).
pub const BYTES_PER_CELL: usize = 1600;
/// Memory besides the grid (the process, the scene).
pub const BASE_BYTES: usize = 16 << 20;
/// CPU time of a 3-D heating study of a Hertz contact a cell of its grid, s (1.2 ms before
/// issue 41, about 40 layers; 0.49 ms since: the sliding sphere at 2 m/s, 12 513 cells, 6.1 s
/// of CPU measured while other builds ran, 2026-11-28).
pub const CPU_SECONDS_PER_CELL: f64 = 5e-4;
/// The heating sheet's sections (25 depths) against the study's 16: its CPU time a cell.
pub const SHEET_CPU_SECONDS_PER_CELL: f64 = 8e-4;
/// The most cells of a Hertz contact's 3-D heating grid: 512 x 512 (it bounds the Péclet
/// number).
pub const MAX_CELLS: usize = 1 << 18;
/// The most cells of a rough map's heating: 2048 x 2048, the same as its contact within the
/// memory allowed (issue 41).
pub const ROUGH_MAX_CELLS: usize = 1 << 22;
/// Peak memory of `thermal` of a rough map a cell, besides [`ROUGH_BASE_BYTES`], for a source
/// slow on the map's scale (the smooth part's lattice not oversampled): measured on issue 41's
/// scenes (`/usr/bin/time -v`, 2026-11-28, after the third part of the speed round), isolated
/// and periodic, 84 and 79 MiB at 256², 299 and 286 MiB at 512², 927 and 1044 MiB at 1024², and
/// 3483 MiB periodic at 2048²: 950 bytes a cell is within 16 % of each. Since the thermal stress
/// operator holds one lattice at a time (issue 41's memory round, the machine loaded), 74 and
/// 70 MiB at 256², 269 and 248 MiB at 512², 814 and 876 MiB at 1024², 3024 MiB periodic at
/// 2048²: within 26 % of each (over at 2048²).
pub const ROUGH_HEATING_BYTES_PER_CELL: usize = 950;
/// Peak memory of `contact` of a rough map a cell (the solve and the subsurface search):
/// measured (issue 41's rough ball, isolated) 40, 126, 472 and 1218 MB at 256², 512², 1024²
/// and 2048² (periodic 36, 117 and 433 MB to 1024²): 360 bytes a cell is within 22 % of each
/// (the search's layers stop growing with the grid at 2048²).
pub const CONTACT_BYTES_PER_CELL: usize = 360;
/// Memory of `contact` and `thermal` of a rough map besides the cells (the process, the
/// scene): the intercept of the measurements.
pub const ROUGH_BASE_BYTES: usize = 12 << 20;
/// CPU time of `contact` of a rough map a cell at 256², s, growing as the square of
/// `log2(cells) / 16` (measured while other builds ran: 14, 19, 24 and 40 µs a cell at 256²,
/// 512², 1024² and 2048²: more iterations and longer transforms on finer maps).
pub const CONTACT_CPU_SECONDS_PER_CELL: f64 = 2e-5;
/// CPU time of the heating of a rough map a cell at 256², s, the contact included, growing as
/// [`CONTACT_CPU_SECONDS_PER_CELL`] does (measured on issue 41's scenes, the machine loaded:
/// 3.4 to 4.3 s at 256², 14 to 18 s at 512², 72 to 90 s at 1024², 508 s periodic at 2048²).
pub const ROUGH_CPU_SECONDS_PER_CELL: f64 = 6e-5;

/// How the CPU time a cell of a rough map grows with the map: `(log2(cells) / 16)²`, at least
/// 1 (more iterations and longer transforms on finer maps).
fn cpu_growth(cells: usize) -> f64 {
    ((cells.max(1) as f64).log2() / 16.0).powi(2).max(1.0)
}

/// The smooth part's extra memory a cell when its lattice is oversampled `over` times in x
/// ([`crate::thermal::stress::ThermalStressOperator::memory_bytes`]): its samples of six
/// components (96 bytes a value of half the lattice's spectrum) and one component's spectrum
/// (32 bytes a cell), each `over` times the unoversampled one's.
fn smooth_bytes_per_cell(over: usize) -> usize {
    (over - 1) * (96 + 2 * 16)
}

/// What `contact` of a rough map of `shape` takes: `(bytes, CPU seconds)`.
pub fn contact_cost(shape: [usize; 2]) -> (usize, f64) {
    let cells = shape[0] * shape[1];
    (
        ROUGH_BASE_BYTES + CONTACT_BYTES_PER_CELL.saturating_mul(cells),
        CONTACT_CPU_SECONDS_PER_CELL * cells as f64 * cpu_growth(cells),
    )
}

/// Peak memory of `contact` of a coated rough map a cell (the layered kernel on a grid four
/// times as wide, and the coating's, interface's and substrate's planes of stress): measured
/// (the coated ball of `scenes/rough_ball_on_b4c_coated_flat.toml` at 128², 256², 512² and
/// 1024², `/usr/bin/time -v`, 2026-11-28) 27, 75, 279 and 972 MiB: 950 bytes a cell is within
/// 11 % of each.
pub const COATED_CONTACT_BYTES_PER_CELL: usize = 950;

/// What `contact` of a rough map of `shape` on a coated body takes: `(bytes, CPU seconds)`.
/// The time is the uncoated contact's estimate, 1.25 times (measured 0.25, 1.3, 6.9 and
/// 36 s of CPU at 128² to 1024², against 0.3, 1, 7 and 33 s for the uncoated estimate).
pub fn coated_contact_cost(shape: [usize; 2]) -> (usize, f64) {
    let cells = shape[0] * shape[1];
    let (_, seconds) = contact_cost(shape);
    (
        ROUGH_BASE_BYTES + COATED_CONTACT_BYTES_PER_CELL.saturating_mul(cells),
        1.25 * seconds,
    )
}

/// What `contact` of a scene's rough map takes, coated or not: `(bytes, CPU seconds, bytes a
/// cell)`.
pub fn rough_contact_cost(scene: &crate::scene::Scene, shape: [usize; 2]) -> (usize, f64, usize) {
    if scene.contact.coating.is_some() {
        let (bytes, seconds) = coated_contact_cost(shape);
        (bytes, seconds, COATED_CONTACT_BYTES_PER_CELL)
    } else {
        let (bytes, seconds) = contact_cost(shape);
        (bytes, seconds, CONTACT_BYTES_PER_CELL)
    }
}

/// CPU time of a wear run a cell of its map and a unit of work, s: the unworn contact's solve
/// and search is one unit, each step [`WEAR_STEP_WORK`] (a warm-started solve and the step's
/// maxima), times [`WEAR_COUNTER_FACTOR`] with a rough counter-surface, [`WEAR_HEATING_FACTOR`]
/// with heating and [`WEAR_COUPLED_FACTOR`] coupled; growing with the map as
/// `(log2(cells) / 16)²` (more iterations and longer transforms on finer maps; unlike
/// [`contact_cost`], not held at 256²'s below it). Fitted to 15 runs (`/usr/bin/time -v` on
/// `wear --json`, 2026-12-07, two cores shared with three builds): the shipped ball's physics
/// at 64², 128², 192², 256² and 512², 10 and 30 steps, plain, with a counter-surface, heated
/// and coupled, and the shipped series; every run within 20 % (`docs/benchmarks.md`).
pub const WEAR_CPU_SECONDS_PER_CELL: f64 = 2.2e-5;
/// A step's work against the unworn contact's, and the steps it is counted over besides the
/// run's (fewer, longer steps take more iterations each: 1.4 times a step's CPU at 10 steps
/// against 30, at 256²).
pub const WEAR_STEP_WORK: f64 = 0.45;
pub const WEAR_EXTRA_STEPS: usize = 2;
/// A step's CPU time with a rough counter-surface (a second, sliding solve a step), against a
/// smooth one: measured 1.74 (128²) and 1.88 (256²).
pub const WEAR_COUNTER_FACTOR: f64 = 1.85;
/// A step's CPU time with `[thermal]` (the flash temperature of each step), against the same
/// run without: measured 1.11 (128²) and 1.13 (256²) with a counter-surface.
pub const WEAR_HEATING_FACTOR: f64 = 1.12;
/// A step's CPU time of a coupled run (`coupled = true`: the thermo-mechanical contact each
/// step), against the isothermal one: measured 1.75 (128²) and 1.63 (256²).
pub const WEAR_COUPLED_FACTOR: f64 = 1.7;
/// Peak memory of a wear run a cell besides the steps' fields
/// ([`crate::study::wear::bytes_per_step`] each) and [`WEAR_BASE_BYTES`]: the solver, the
/// evolution's own maps and the search; measured 450 to 560 bytes a cell from 128² to 512².
pub const WEAR_BYTES_PER_CELL: usize = 560;
pub const WEAR_BASE_BYTES: usize = 10 << 20;
/// Memory a cell of the flash temperature's operators (measured +5.8 MiB at 256²: 92 bytes a
/// cell), and of a coupled run's (+19 MiB at 256²: 300 bytes a cell).
pub const WEAR_HEATING_BYTES_PER_CELL: usize = 100;
pub const WEAR_COUPLED_BYTES_PER_CELL: usize = 300;

/// What `wear` of a scene with `[wear]` or `[[series]]` takes on a map of `shape`: `(bytes, CPU
/// seconds)` of the whole run, every step with its maxima and heating (issue 50: `check`
/// stated one contact's estimate, which the run exceeded 1.3 to 1.6 times, and none for a
/// heated run). A scene without wear: its contact's ([`rough_contact_cost`]).
pub fn wear_cost(scene: &crate::scene::Scene, shape: [usize; 2]) -> (usize, f64) {
    let Some(spec) = &scene.wear else {
        let (bytes, seconds, _) = rough_contact_cost(scene, shape);
        return (bytes, seconds);
    };
    let cells = shape[0] * shape[1];
    let steps = crate::study::wear::step_count(spec);
    let counter = scene.surface.as_ref().is_some_and(|s| s.counter.is_some());
    let coupled = scene.thermal.as_ref().is_some_and(|t| t.coupled);
    let mut step = WEAR_STEP_WORK;
    if counter {
        step *= WEAR_COUNTER_FACTOR;
    }
    let mut heating_per_cell = 0;
    if scene.thermal.is_some() {
        step *= WEAR_HEATING_FACTOR;
        heating_per_cell = WEAR_HEATING_BYTES_PER_CELL;
    }
    if coupled {
        step *= WEAR_COUPLED_FACTOR;
        heating_per_cell = WEAR_COUPLED_BYTES_PER_CELL;
    }
    let growth = ((cells.max(2) as f64).log2() / 16.0).powi(2);
    let seconds = WEAR_CPU_SECONDS_PER_CELL
        * cells as f64
        * growth
        * (1.0 + step * (steps + WEAR_EXTRA_STEPS) as f64);
    let bytes = WEAR_BASE_BYTES
        .saturating_add((WEAR_BYTES_PER_CELL + heating_per_cell).saturating_mul(cells))
        .saturating_add(crate::study::wear::bytes_per_step(shape).saturating_mul(steps));
    (bytes, seconds)
}

/// The heating of a scene as planned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HeatingPlan {
    /// The grid of the study, `[ny, nx]` (a line contact: rows of strips; gears: the largest
    /// grid along the path).
    pub shape: [usize; 2],
    /// A plane problem (line contact, gears).
    pub line: bool,
    /// Peak memory, bytes.
    pub bytes: usize,
    /// CPU time of the study, and of the heating sheet besides it, s.
    pub cpu_seconds: f64,
    pub sheet_cpu_seconds: f64,
}

impl HeatingPlan {
    fn of_grid(shape: [usize; 2], line: bool, rough_bytes: usize) -> Self {
        let cells = shape[0] * shape[1];
        // A plane problem's heavy part is the contact's DC-FFT layer over the rows: a
        // twentieth of the 3-D cost a cell, generously.
        let time = if line { 0.05 } else { 1.0 };
        Self {
            shape,
            line,
            bytes: (BASE_BYTES + BYTES_PER_CELL.saturating_mul(cells)).max(rough_bytes),
            cpu_seconds: time * CPU_SECONDS_PER_CELL * cells as f64,
            sheet_cpu_seconds: time * SHEET_CPU_SECONDS_PER_CELL * cells as f64,
        }
    }

    /// `"129 x 97 cells, about 8 s of CPU (the heating sheet 10 s more) and 36 MiB"`.
    pub fn summary(&self) -> String {
        format!(
            "{} x {} cells, about {} of CPU (the heating sheet {} more) and {}",
            self.shape[1],
            self.shape[0],
            duration(self.cpu_seconds),
            duration(self.sheet_cpu_seconds),
            crate::io::text::bytes(self.bytes as u64)
        )
    }
}

/// `"0.4 s"`, `"12 s"`, `"3.5 min"`, `"2.1 h"`.
pub fn duration(seconds: f64) -> String {
    if seconds < 1.0 {
        format!("{seconds:.1} s")
    } else if seconds < 120.0 {
        format!("{seconds:.0} s")
    } else if seconds < 7200.0 {
        format!("{:.1} min", seconds / 60.0)
    } else {
        format!("{:.1} h", seconds / 3600.0)
    }
}

/// Why the heating of a scene cannot be computed here: the key the scene wrote, the message
/// and the fix.
#[derive(Clone, Debug, PartialEq)]
pub struct Refusal {
    pub key: String,
    pub message: String,
    pub hint: String,
}

/// Plans the heating of `scene`: `None` without `[thermal]`, else its grid and cost, or why
/// it is refused (module doc).
pub fn plan(scene: &Scene) -> Result<Option<HeatingPlan>, Refusal> {
    let Some(spec) = &scene.thermal else {
        return Ok(None);
    };
    if let Some(mesh) = &spec.gear {
        return gears(scene, mesh).map(Some);
    }
    match scene.contact.kind {
        ContactKind::Line | ContactKind::Point | ContactKind::Elliptical => {
            hertz(scene, spec).map(Some)
        }
        ContactKind::Rough => rough(scene, spec).map(Some),
        ContactKind::Tractions | ContactKind::Surface => Ok(None),
    }
}

/// The study's grid of a Hertz contact: refined with the speed, so a grid beyond the limits
/// is refused under the key of the speed that asks for it.
fn hertz(scene: &Scene, spec: &ThermalSpec) -> Result<HeatingPlan, Refusal> {
    let layout = hertz_layout(scene, spec, &STUDY_WINDOW).map_err(|e| speed_refusal(scene, &e))?;
    let line = scene.contact.kind == ContactKind::Line;
    let plan = HeatingPlan::of_grid(layout.shape, line, 0);
    let cells = layout.shape[0] * layout.shape[1];
    if !line && (cells > MAX_CELLS || plan.bytes > memory_limit_bytes()) {
        let a = scene.contact.half_width_m();
        let (body, fastest) = fastest(spec);
        let peclet = inverse_length(fastest) * a;
        // The grid takes about 12 (u a)² cells (4a by 3b in cells of 1/u and b/(a u)).
        let limit = ((MAX_CELLS as f64) / 12.0).sqrt();
        return Err(Refusal {
            key: spec.speed_keys[body - 1].to_string(),
            message: format!(
                "at {} m/s over body {body} (Péclet number V a/(2κ) = {}) the heating grid needs cells of at most 1/u = {} µm: {}, more than the {} cells allowed ({})",
                crate::io::text::significant(fastest.speed_m_per_s, 4, 1e6, true),
                crate::io::text::significant(peclet, 4, 1e6, true),
                crate::io::text::significant(1e6 / inverse_length(fastest), 4, 1e9, true),
                plan.summary(),
                MAX_CELLS,
                limit_text()
            ),
            hint: format!(
                "lower the speed: these bodies are heated up to a Péclet number of about {limit:.0}; beyond, the flash temperature follows the fast limit of Jaeger and Blok, growing as √Pe"
            ),
        });
    }
    Ok(plan)
}

/// Body (1 or 2) with the largest `u = V/(2κ)`, and its properties.
fn fastest(spec: &ThermalSpec) -> (usize, &crate::scene::ThermalBody) {
    match &spec.body2 {
        Some(b2) if inverse_length(b2) > inverse_length(&spec.body1) => (2, b2),
        _ => (1, &spec.body1),
    }
}

/// What the limit of [`MAX_CELLS`] costs.
fn limit_text() -> String {
    let most = HeatingPlan::of_grid([512, 512], false, 0);
    format!(
        "512 x 512, about {} of CPU and {}",
        duration(most.cpu_seconds),
        crate::io::text::bytes(most.bytes as u64)
    )
}

/// A Hertz grid that cannot resolve the speed (the cell Péclet number beyond
/// [`MAX_CELL_PECLET`] at 640 cells): refused under the speed's key.
fn speed_refusal(scene: &Scene, error: &ThermalStudyError) -> Refusal {
    match error {
        ThermalStudyError::CellPeclet {
            key,
            body,
            cell_peclet,
            hint,
        } => {
            let a = scene.contact.half_width_m();
            let peclet = scene
                .thermal
                .as_ref()
                .map(|spec| {
                    let b = if *body == 2 {
                        spec.body2.as_ref().unwrap_or(&spec.body1)
                    } else {
                        &spec.body1
                    };
                    inverse_length(b) * a
                })
                .unwrap_or(f64::NAN);
            Refusal {
                key: (*key).to_string(),
                message: format!(
                    "body {body}'s Péclet number V a/(2κ) is {}: the heat penetrates less than a cell while the contact crosses one (cell Péclet number {:.3} on the finest grid, 640 cells across 4a; at most {MAX_CELL_PECLET})",
                    crate::io::text::significant(peclet, 4, 1e9, true),
                    cell_peclet
                ),
                hint: (*hint).to_string(),
            }
        }
        other => Refusal {
            key: "thermal".into(),
            message: other.to_string(),
            hint: "check the [thermal] table".into(),
        },
    }
}

/// A rough scene: the grid is the map's, so its size is refused under the map's key, a speed
/// its samples cannot resolve under the speed's.
fn rough(scene: &Scene, spec: &ThermalSpec) -> Result<HeatingPlan, Refusal> {
    let Some(surface) = &scene.surface else {
        return Ok(HeatingPlan::of_grid([0, 0], false, 0));
    };
    let [ny, nx] = surface.heights.shape();
    let [dx, _] = surface.heights.spacing_m();
    for (index, body) in std::iter::once(&spec.body1)
        .chain(spec.body2.iter())
        .enumerate()
    {
        let cell_peclet = inverse_length(body) * dx;
        if cell_peclet > MAX_CELL_PECLET * (1.0 + 1e-9) {
            return Err(Refusal {
                key: spec.speed_keys[index.min(1)].to_string(),
                message: format!(
                    "at {} m/s over body {} the cell Péclet number V dx/(2κ) of the map's {} µm samples is {cell_peclet:.3}, more than {MAX_CELL_PECLET}: the heat penetrates less than a sample while the contact crosses one",
                    crate::io::text::significant(body.speed_m_per_s, 4, 1e6, true),
                    index + 1,
                    crate::io::text::significant(dx * 1e6, 4, 1e9, true)
                ),
                hint: format!(
                    "lower the speed (at most {} m/s with these samples), or sample the surface more finely",
                    crate::io::text::significant(
                        MAX_CELL_PECLET * 2.0 * body.properties.diffusivity_m2_per_s / dx,
                        3,
                        1e9,
                        true
                    )
                ),
            });
        }
    }
    let cells = ny * nx;
    let (contact_bytes, contact_seconds) = contact_cost([ny, nx]);
    // The smooth part's oversampling for the fastest body ([`crate::thermal::stress`]).
    let dy = surface.heights.spacing_m()[1];
    let u = std::iter::once(&spec.body1)
        .chain(spec.body2.iter())
        .map(inverse_length)
        .fold(0.0, f64::max);
    let over = crate::thermal::stress::smooth_oversampling_of([ny, nx], [dx, dy], u);
    let heating_bytes = ROUGH_BASE_BYTES.saturating_add(
        (ROUGH_HEATING_BYTES_PER_CELL + smooth_bytes_per_cell(over)).saturating_mul(cells),
    );
    let plan = HeatingPlan {
        shape: [ny, nx],
        line: false,
        bytes: heating_bytes.max(contact_bytes),
        cpu_seconds: (ROUGH_CPU_SECONDS_PER_CELL * cells as f64 * cpu_growth(cells))
            .max(contact_seconds),
        // The sheet's 25 depths against the search's (about 37): about as long again.
        sheet_cpu_seconds: ROUGH_CPU_SECONDS_PER_CELL * cells as f64 * cpu_growth(cells),
    };
    if cells > ROUGH_MAX_CELLS || plan.bytes > memory_limit_bytes() {
        let key = if surface.generated {
            "surface.generate.samples"
        } else {
            "surface.file"
        };
        return Err(Refusal {
            key: key.into(),
            message: format!(
                "the heating of a {nx} x {ny} map needs {}: more than the heating allows (2048 x 2048 cells, memory within {})",
                plan.summary(),
                crate::io::text::bytes(memory_limit_bytes() as u64)
            ),
            hint: "use a coarser map for the heating (half the samples a side takes a quarter of the time and memory), or remove [thermal] to solve the contact alone".into(),
        });
    }
    Ok(plan)
}

/// Running gears: every point of the path is a line contact whose grid must resolve the
/// flanks' speeds there; refused under `thermal.pinion_speed`, naming the point.
fn gears(scene: &Scene, mesh: &crate::scene::GearMesh) -> Result<HeatingPlan, Refusal> {
    let Some(pair) = scene.contact.dimensional.and_then(|d| d.gears) else {
        return Ok(HeatingPlan::of_grid([0, 0], true, 0));
    };
    let mut largest = [0, 0];
    for s in path_positions(&pair) {
        // The grid does not depend on the sliding speed (only the flux does).
        let Some((at, point)) = scene_at(scene, mesh, s, 1.0) else {
            continue;
        };
        let Some(spec) = &at.thermal else { continue };
        match hertz_layout(&at, spec, &STUDY_WINDOW) {
            Ok(layout) => {
                if layout.shape[0] * layout.shape[1] > largest[0] * largest[1] {
                    largest = layout.shape;
                }
            }
            Err(error) => {
                let mut refusal = speed_refusal(&at, &error);
                refusal.message = format!(
                    "at {} rpm, at s = {} mm on the path of contact the flanks move at {} and {} m/s (the contact half-width {} µm): {}",
                    crate::io::text::significant(
                        mesh.pinion_rad_per_s * 30.0 / std::f64::consts::PI,
                        6,
                        1e9,
                        true
                    ),
                    crate::io::text::significant(s * 1e3, 4, 1e6, true),
                    crate::io::text::significant(point.flank_speeds_m_per_s[0], 4, 1e9, true),
                    crate::io::text::significant(point.flank_speeds_m_per_s[1], 4, 1e9, true),
                    crate::io::text::significant(point.half_width_m * 1e6, 4, 1e9, true),
                    refusal.message
                );
                refusal.hint = "lower thermal.pinion_speed (or use smaller teeth, contact.gears.module: the Péclet number grows with the flank speed and the contact's width)".into();
                return Err(refusal);
            }
        }
    }
    Ok(HeatingPlan::of_grid(largest, true, 0))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sphere(speed: &str) -> Scene {
        let text = format!(
            "format = 1\n[contact]\nkind = \"point\"\nload = \"500 N\"\nfriction = 0.1\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"20 mm\"\nmaterial = \"steel\"\n[thermal]\nspeed = \"{speed}\"\npartition = \"blok\"\n"
        );
        Scene::parse(&text, "s", "s.toml").expect("valid scene")
    }

    /// A coated rough map is estimated with the coated constants (its layered kernel and
    /// stress planes take about 2.6 times the memory of an uncoated contact), an uncoated one
    /// with the contact's; the shipped coated scene's estimate is within 11 % of the 75 MiB
    /// measured.
    #[test]
    fn a_coated_rough_map_is_estimated_as_coated() {
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("scenes/rough_ball_on_b4c_coated_flat.toml"),
        )
        .expect("shipped scene");
        let coated = Scene::parse(&text, "c", "c.toml").expect("valid scene");
        let start = text.find("[contact.body1.coating]").expect("a coating");
        let end = start + text[start..].find("\n\n").expect("a blank line after it");
        let bare = Scene::parse(
            &format!("{}{}", &text[..start], &text[end..]),
            "u",
            "u.toml",
        )
        .expect("valid without the coating");
        assert!(bare.contact.coating.is_none());
        let shape = [256, 256];
        let (bytes, seconds, per_cell) = rough_contact_cost(&coated, shape);
        assert_eq!(per_cell, COATED_CONTACT_BYTES_PER_CELL);
        assert_eq!((bytes, seconds), coated_contact_cost(shape));
        let measured = 74.5 * (1u64 << 20) as f64;
        assert!((bytes as f64 / measured - 1.0).abs() < 0.11, "{bytes}");
        let (bare_bytes, bare_seconds, bare_per_cell) = rough_contact_cost(&bare, shape);
        assert_eq!(bare_per_cell, CONTACT_BYTES_PER_CELL);
        assert_eq!((bare_bytes, bare_seconds), contact_cost(shape));
        assert!(bytes > 2 * bare_bytes && seconds > bare_seconds);
    }

    /// The plan is of the grid the study takes, and its cost follows the measured constants;
    /// the Péclet number the limit allows is the one the refusal states.
    #[test]
    fn the_plan_is_the_studys_grid_and_the_limit_is_stated() {
        for speed in ["0.1 m/s", "2 m/s", "6 m/s"] {
            let scene = sphere(speed);
            let spec = scene.thermal.expect("[thermal]");
            let plan = plan(&scene).expect("within the limits").expect("heated");
            let grid = crate::study::thermal::hertz_grid(&scene, &spec, &STUDY_WINDOW)
                .expect("the study's grid");
            assert_eq!(plan.shape, grid.shape, "{speed}");
            let cells = (plan.shape[0] * plan.shape[1]) as f64;
            assert_eq!(plan.cpu_seconds, CPU_SECONDS_PER_CELL * cells);
            assert_eq!(plan.bytes, BASE_BYTES + BYTES_PER_CELL * cells as usize);
        }
        // About 12 (u a)² cells: Pe 140 passes, Pe 160 is refused under the speed's key.
        let a = sphere("1 m/s").contact.half_width_m();
        let kappa = crate::thermal::material::thermal_preset("steel")
            .expect("steel")
            .diffusivity_m2_per_s;
        let at = |peclet: f64| format!("{} m/s", peclet * 2.0 * kappa / a);
        plan(&sphere(&at(140.0))).expect("Pe 140");
        let refusal = plan(&sphere(&at(160.0))).expect_err("Pe 160");
        assert_eq!(refusal.key, "thermal.speed");
        assert!(refusal.hint.contains("about 148"), "{}", refusal.hint);
    }
}
