//! Rerun recordings (issue 5): recorded into memory and read back as chunks, asserting entity
//! paths, the number of time points and values; and a written `.rrd` file decoded.

use std::collections::BTreeMap;

use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};
use stressfield::record::{self, APPLICATION_ID};
use stressfield::scene::Scene;
use stressfield::solution::line_hertz;

/// What a recording holds: per entity path, its chunks.
struct Contents {
    chunks: BTreeMap<String, Vec<Chunk>>,
    application_ids: Vec<String>,
    /// Blueprint stores (viewer layouts) among the messages.
    blueprints: usize,
}

impl Contents {
    fn from_messages(messages: impl IntoIterator<Item = LogMsg>) -> Self {
        let mut chunks: BTreeMap<String, Vec<Chunk>> = BTreeMap::new();
        let mut application_ids = Vec::new();
        let mut blueprints = 0;
        for message in messages {
            match message {
                // The viewer layout (blueprint store) is not the data.
                LogMsg::ArrowMsg(store, _) if store.kind() != rerun::StoreKind::Recording => {}
                LogMsg::ArrowMsg(_, arrow) => {
                    let chunk = Chunk::from_arrow_msg(&arrow).expect("a valid chunk");
                    chunks
                        .entry(chunk.entity_path().to_string())
                        .or_default()
                        .push(chunk);
                }
                LogMsg::SetStoreInfo(info) => {
                    application_ids.push(info.info.application_id().to_string());
                    blueprints +=
                        usize::from(info.info.store_id.kind() == rerun::StoreKind::Blueprint);
                }
                LogMsg::BlueprintActivationCommand(_) => {}
            }
        }
        Self {
            chunks,
            application_ids,
            blueprints,
        }
    }

    fn paths(&self) -> Vec<&str> {
        self.chunks.keys().map(String::as_str).collect()
    }

    /// The scalars logged at `path`, ordered by their time on `timeline`.
    fn scalars(&self, path: &str, timeline: &'static str) -> Vec<(i64, f64)> {
        let mut values = Vec::new();
        for chunk in self
            .chunks
            .get(path)
            .unwrap_or_else(|| panic!("no entity {path}"))
        {
            let times = chunk
                .timelines()
                .get(&rerun::TimelineName::from(timeline))
                .unwrap_or_else(|| panic!("{path} is not on the timeline {timeline}"))
                .times_raw()
                .to_vec();
            let batches = chunk.iter_component::<rerun::components::Scalar>(
                rerun::Scalars::descriptor_scalars().component,
            );
            for (time, batch) in times.into_iter().zip(batches) {
                for scalar in batch.iter() {
                    values.push((time, scalar.0 .0));
                }
            }
        }
        values.sort_by_key(|(time, _)| *time);
        values
    }

    /// The number of rows logged at `path`.
    fn rows(&self, path: &str) -> usize {
        self.chunks
            .get(path)
            .map_or(0, |chunks| chunks.iter().map(Chunk::num_rows).sum())
    }

    /// The number of rows logged at `path` on `timeline` (static rows, such as a placement,
    /// are not counted).
    fn rows_on(&self, path: &str, timeline: &'static str) -> usize {
        let name = rerun::TimelineName::from(timeline);
        self.chunks.get(path).map_or(0, |chunks| {
            chunks
                .iter()
                .filter(|chunk| chunk.timelines().contains_key(&name))
                .map(Chunk::num_rows)
                .sum()
        })
    }
}

/// The positions of the `Points3D` in a chunk.
fn positions_3d(chunk: &Chunk) -> Vec<[f32; 3]> {
    chunk
        .iter_component::<rerun::components::Position3D>(
            rerun::Points3D::descriptor_positions().component,
        )
        .flat_map(|batch| {
            batch
                .iter()
                .map(|p| [p.x(), p.y(), p.z()])
                .collect::<Vec<_>>()
        })
        .collect()
}

fn record_in_memory(scene: &Scene) -> (record::Summary, Contents) {
    let (stream, storage) = rerun::RecordingStreamBuilder::new(APPLICATION_ID)
        .memory()
        .expect("an in-memory recording");
    let rows = std::sync::atomic::AtomicUsize::new(0);
    let on_row = || {
        rows.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    };
    let summary = record::record_scene(scene, &stream, &on_row).expect("recorded");
    // Progress: one call per evaluated row.
    assert_eq!(rows.into_inner(), record::rows(scene));
    stream.flush_blocking().expect("flushed");
    (summary, Contents::from_messages(storage.take()))
}

fn scene(text: &str) -> Scene {
    Scene::parse(text, "test", "test.toml").expect("a valid scene")
}

const FRICTION_SWEEP: &str = r#"
format = 1
[contact]
kind = "line"
poisson = 0.3
[figure]
quantity = "von_mises"
x = [-2.5, 2.5]
z = [0.0, 2.0]
resolution = 201
[sweep]
parameter = "friction"
from = 0.0
to = 0.5
steps = 6
"#;

#[test]
fn a_friction_sweep_has_one_time_point_per_step_and_the_maxima_of_the_closed_form() {
    let (summary, contents) = record_in_memory(&scene(FRICTION_SWEEP));
    assert_eq!(summary.steps, 6);
    for path in [
        "/description",
        "/log",
        "/sections/0/field",
        "/sections/0/values",
        "/sections/0/surface",
        "/sections/0/tractions",
        "/sections/0/maximum",
        "/series/0/maximum",
        "/series/0/maximum_depth",
        "/series/friction",
    ] {
        assert!(
            contents.paths().contains(&path),
            "{path} missing from {:?}",
            contents.paths()
        );
    }
    assert_eq!(
        contents.application_ids,
        vec![APPLICATION_ID.to_string(); contents.application_ids.len()]
    );
    // One image per step (plus the static transform's row).
    assert_eq!(contents.rows("/sections/0/values"), 6);
    let friction = contents.scalars("/series/friction", "friction");
    let expected: Vec<(i64, f64)> = (0..6).map(|k| (k, 0.1 * k as f64)).collect();
    assert_eq!(friction.len(), 6);
    for ((t, mu), (te, mue)) in friction.iter().zip(&expected) {
        assert_eq!(t, te);
        assert!((mu - mue).abs() < 1e-12);
    }
    // mu = 0: the von Mises maximum 0.557 p0 at z = 0.70a (Johnson 1985, §4.2(b)), on a grid of
    // 0.025a; at mu = 0.5 it is on the surface (0.7 = 0.70a within one grid step).
    let maxima = contents.scalars("/series/0/maximum", "friction");
    let depths = contents.scalars("/series/0/maximum_depth", "friction");
    assert!((maxima[0].1 - 0.5572).abs() < 2e-3, "{maxima:?}");
    assert!((depths[0].1 - 0.70).abs() < 0.03, "{depths:?}");
    assert_eq!(depths[5].1, 0.0, "{depths:?}");
    // The maximum rises with friction.
    assert!(maxima.windows(2).all(|w| w[1].1 > w[0].1), "{maxima:?}");
}

#[test]
fn a_moving_load_records_the_stress_history_of_material_points() {
    let text = r#"
format = 1
[contact]
kind = "line"
poisson = 0.3
[figure]
quantity = "sxz"
x = [-3.0, 3.0]
z = [0.0, 2.0]
resolution = 61
[sweep]
parameter = "position"
values = [-2.0, -0.8660254037844386, 0.0, 0.8660254037844386, 2.0]
material_points = [[0.0, 0.5], [1.0, 0.25]]
"#;
    let (summary, contents) = record_in_memory(&scene(text));
    assert_eq!(summary.steps, 5);
    // Orthogonal shear at (0, a/2) with the load at x0: the closed form at (-x0, a/2), which
    // reaches -p0/4 and +p0/4 at x0 = -/+ (sqrt 3 / 2) a (Johnson 1985, §4.2; the extreme
    // p0/4 is also asserted in tests/line_contact.rs).
    let history = contents.scalars("/history/0/point0/sxz", "position");
    assert_eq!(history.len(), 5);
    let positions = [-2.0, -0.8660254037844386, 0.0, 0.8660254037844386, 2.0];
    for ((_, got), x0) in history.iter().zip(positions) {
        let expected = line_hertz::stress_over_p0(-x0, 0.5, 0.0, 0.3).xz;
        assert!(
            (got - expected).abs() < 1e-12,
            "x0 = {x0}: {got} vs {expected}"
        );
    }
    // Under this sign convention the point sees -p0/4 while the load approaches (x0 < 0)
    // and +p0/4 after it has passed.
    assert!((history[1].1 + 0.25).abs() < 1e-9, "{history:?}");
    assert!((history[3].1 - 0.25).abs() < 1e-9, "{history:?}");
    // The second point, off the axis.
    let other = contents.scalars("/history/0/point1/szz", "position");
    for ((_, got), x0) in other.iter().zip(positions) {
        let expected = line_hertz::stress_over_p0(1.0 - x0, 0.25, 0.0, 0.3).zz;
        assert!((got - expected).abs() < 1e-12);
    }
    assert!(contents.paths().contains(&"/sections/0/material_points"));
}

#[test]
fn a_sphere_volume_is_a_point_cloud_above_the_threshold_with_its_maximum() {
    let text = r#"
format = 1
[contact]
kind = "point"
poisson = 0.3
[figure]
quantity = "von_mises"
x = [-2.0, 2.0]
z = [0.0, 1.6]
resolution = 81
[volume]
x = [-2.0, 2.0]
y = [-2.0, 2.0]
z = [0.0, 2.0]
points = 41
threshold = 0.5
"#;
    let (summary, contents) = record_in_memory(&scene(text));
    assert!(summary.volume_points > 100, "{summary:?}");
    for path in [
        "/volume",
        "/volume/points",
        "/volume/contact",
        "/volume/maximum",
    ] {
        assert!(contents.paths().contains(&path), "{path} missing");
    }
    let positions = positions_3d(&contents.chunks["/volume/points"][0]);
    assert_eq!(positions.len(), summary.volume_points);
    assert!(positions.iter().all(|p| p[2] >= 0.0 && p[2] <= 2.0));
    // Symmetric in y for a frictionless sphere: the cloud's mean y is zero.
    let mean_y = positions.iter().map(|p| f64::from(p[1])).sum::<f64>() / positions.len() as f64;
    assert!(mean_y.abs() < 1e-6, "{mean_y}");
    // The maximum is on the axis at z = 0.48a (Johnson 1985, §3.4(b)), on a 0.1a grid.
    let at = positions_3d(&contents.chunks["/volume/maximum"][0]);
    assert_eq!(at.len(), 1);
    assert!(at[0][0].abs() < 1e-6 && at[0][1].abs() < 1e-6, "{at:?}");
    assert!((at[0][2] - 0.5).abs() < 0.06, "{at:?}");
}

#[test]
fn a_recording_written_to_a_file_decodes_with_its_entities() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("sweep.rrd");
    let summary = record::record_to_file(&scene(FRICTION_SWEEP), &path, &|| {}).expect("recorded");
    assert_eq!(summary.steps, 6);
    let file = std::fs::File::open(&path).expect("the file exists");
    let messages: Vec<LogMsg> = DecoderApp::decode_lazy(std::io::BufReader::new(file))
        .map(|message| message.expect("a valid message"))
        .collect();
    let contents = Contents::from_messages(messages);
    assert!(!contents.application_ids.is_empty());
    assert!(contents
        .application_ids
        .iter()
        .all(|id| id == APPLICATION_ID));
    assert!(contents.paths().contains(&"/sections/0/field"));
    assert_eq!(contents.scalars("/series/0/maximum", "friction").len(), 6);
    // The file carries its viewer layout.
    assert!(contents.blueprints >= 1);
    // Nothing else was left in the directory (no temporary file).
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .expect("listed")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert_eq!(names, vec![std::ffi::OsString::from("sweep.rrd")]);
}

#[test]
fn an_unwritable_recording_fails_and_leaves_nothing() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("missing").join("sweep.rrd");
    let error = record::record_to_file(&scene(FRICTION_SWEEP), &path, &|| {})
        .expect_err("the directory does not exist");
    assert!(error.to_string().contains("cannot write"), "{error}");
    assert!(!path.exists());
    assert_eq!(std::fs::read_dir(dir.path()).expect("listed").count(), 0);
}

#[test]
fn every_shipped_recording_scene_records() {
    let mut recorded = 0;
    for entry in std::fs::read_dir("scenes").expect("scenes/") {
        let path = entry.expect("entry").path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let scene = Scene::load(&path).expect("a valid scene");
        if scene.sweep.is_none() && scene.volume.is_none() {
            continue;
        }
        let (summary, contents) = record_in_memory(&scene);
        let steps = scene.sweep.as_ref().map_or(1, |s| s.values.len());
        assert_eq!(summary.steps, steps, "{}", path.display());
        // A rough contact's load sweep logs its pressure map at every load (and places it
        // once, statically).
        if scene.contact.kind == stressfield::scene::ContactKind::Rough {
            let timeline = record::timeline(&scene);
            assert_eq!(
                contents.rows_on("/contact/field", timeline),
                steps,
                "{}",
                path.display()
            );
        } else {
            assert_eq!(
                contents.rows("/sections/0/values"),
                steps,
                "{}",
                path.display()
            );
        }
        recorded += 1;
    }
    assert!(recorded >= 4, "{recorded} recording scenes");
}
