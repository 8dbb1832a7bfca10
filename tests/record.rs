//! Rerun recordings (issue 5): recorded into memory and read back as chunks, asserting entity
//! paths, the number of time points and values; and a written `.rrd` file decoded.

use std::collections::BTreeMap;

use rerun::external::re_log_encoding::DecoderApp;
use rerun::log::{Chunk, LogMsg};
use stressfield::record::{self, APPLICATION_ID};
use stressfield::scene::{Scene, SweepParameter};
use stressfield::solution::line_hertz;

/// What a recording holds: per entity path, its chunks.
pub(crate) struct Contents {
    pub(crate) chunks: BTreeMap<String, Vec<Chunk>>,
    /// The viewer layout's chunks, by blueprint entity path.
    layout: BTreeMap<String, Vec<Chunk>>,
    application_ids: Vec<String>,
    /// Blueprint stores (viewer layouts) among the messages.
    blueprints: usize,
}

impl Contents {
    pub(crate) fn from_messages(messages: impl IntoIterator<Item = LogMsg>) -> Self {
        let mut chunks: BTreeMap<String, Vec<Chunk>> = BTreeMap::new();
        let mut layout: BTreeMap<String, Vec<Chunk>> = BTreeMap::new();
        let mut application_ids = Vec::new();
        let mut blueprints = 0;
        for message in messages {
            match message {
                // The viewer layout (blueprint store) is not the data.
                LogMsg::ArrowMsg(store, arrow) if store.kind() != rerun::StoreKind::Recording => {
                    let chunk = Chunk::from_arrow_msg(&arrow).expect("a valid chunk");
                    layout
                        .entry(chunk.entity_path().to_string())
                        .or_default()
                        .push(chunk);
                }
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
            layout,
            application_ids,
            blueprints,
        }
    }

    pub(crate) fn paths(&self) -> Vec<&str> {
        self.chunks.keys().map(String::as_str).collect()
    }

    /// The scalars logged at `path`, ordered by their time on `timeline`.
    pub(crate) fn scalars(&self, path: &str, timeline: &'static str) -> Vec<(i64, f64)> {
        let mut values = Vec::new();
        for chunk in self
            .chunks
            .get(path)
            .unwrap_or_else(|| panic!("no entity {path}"))
        {
            // The series' style (name, colour) is static.
            if chunk.is_static() {
                continue;
            }
            // Values logged on other timelines only (a rough sweep's charts hold the scene's
            // load's values on `depth` too) are not on this one.
            let Some(times) = chunk.timelines().get(&rerun::TimelineName::from(timeline)) else {
                continue;
            };
            let times = times.times_raw().to_vec();
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

    /// The labels logged at `path` (a `Points2D`), every row in order.
    pub(crate) fn labels(&self, path: &str) -> Vec<String> {
        texts(
            self.chunks
                .get(path)
                .unwrap_or_else(|| panic!("no entity {path}")),
            rerun::Points2D::descriptor_labels().component,
        )
    }

    /// The texts of the recording's text documents (the scene's description or report).
    pub(crate) fn text_documents(&self) -> Vec<String> {
        texts(
            self.chunks.values().flatten(),
            rerun::TextDocument::descriptor_text().component,
        )
    }

    /// The names of the layout's views, as the viewer shows them on their tabs.
    pub(crate) fn view_names(&self) -> Vec<String> {
        use rerun::external::re_sdk_types::blueprint::archetypes::ViewBlueprint;
        self.layout
            .values()
            .flatten()
            .flat_map(|chunk| {
                chunk
                    .iter_component::<rerun::components::Name>(
                        ViewBlueprint::descriptor_display_name().component,
                    )
                    .flat_map(|batch| {
                        batch
                            .iter()
                            .map(|n| n.as_str().to_string())
                            .collect::<Vec<_>>()
                    })
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    /// The texts of one component of the time panel's blueprint.
    fn time_panel<C: rerun::Component>(
        &self,
        component: rerun::ComponentIdentifier,
        text: impl Fn(&C) -> String,
    ) -> Vec<String> {
        self.layout
            .get("/time_panel")
            .into_iter()
            .flatten()
            .flat_map(|chunk| {
                chunk
                    .iter_component::<C>(component)
                    .flat_map(|batch| batch.iter().map(&text).collect::<Vec<_>>())
                    .collect::<Vec<_>>()
            })
            .collect()
    }

    /// The time panel's play state as the layout opens it (Paused at the first step, or
    /// Following the newest).
    fn play_state(&self) -> Vec<String> {
        use rerun::external::re_sdk_types::blueprint::archetypes::TimePanelBlueprint;
        self.time_panel(
            TimePanelBlueprint::descriptor_play_state().component,
            |s: &rerun::blueprint::components::PlayState| s.to_string(),
        )
    }

    /// The timeline the time panel opens on.
    pub(crate) fn time_panel_timeline(&self) -> Vec<String> {
        use rerun::external::re_sdk_types::blueprint::archetypes::TimePanelBlueprint;
        self.time_panel(
            TimePanelBlueprint::descriptor_timeline().component,
            |s: &rerun::blueprint::components::TimelineName| s.0.to_string(),
        )
    }

    /// The blueprint entities whose path ends with `suffix`.
    fn layout_paths(&self, suffix: &str) -> Vec<&str> {
        self.layout
            .keys()
            .map(String::as_str)
            .filter(|p| p.ends_with(suffix))
            .collect()
    }

    /// The number of rows logged at `path`.
    fn rows(&self, path: &str) -> usize {
        self.chunks
            .get(path)
            .map_or(0, |chunks| chunks.iter().map(Chunk::num_rows).sum())
    }

    /// The times on `timeline` of the rows logged at `path` that are not on `other`, in order.
    pub(crate) fn times_on(
        &self,
        path: &str,
        timeline: &'static str,
        other: &'static str,
    ) -> Vec<i64> {
        let (name, other) = (
            rerun::TimelineName::from(timeline),
            rerun::TimelineName::from(other),
        );
        let mut times: Vec<i64> = self
            .chunks
            .get(path)
            .unwrap_or_else(|| panic!("no entity {path}"))
            .iter()
            .filter(|chunk| !chunk.timelines().contains_key(&other))
            .filter_map(|chunk| chunk.timelines().get(&name))
            .flat_map(|column| column.times_raw().to_vec())
            .collect();
        times.sort_unstable();
        times
    }

    /// The number of rows logged at `path` on `timeline` (static rows, such as a placement,
    /// are not counted).
    pub(crate) fn rows_on(&self, path: &str, timeline: &'static str) -> usize {
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

/// The points of the `LineStrips2D` logged at `path` (every row, every strip, in order).
pub(crate) fn strip_points_2d(contents: &Contents, path: &str) -> Vec<[f32; 2]> {
    contents
        .chunks
        .get(path)
        .into_iter()
        .flatten()
        .flat_map(|chunk| {
            chunk
                .iter_component::<rerun::components::LineStrip2D>(
                    rerun::LineStrips2D::descriptor_strips().component,
                )
                .flat_map(|batch| {
                    batch
                        .iter()
                        .flat_map(|strip| {
                            strip.0.iter().map(|p| [p.x(), p.y()]).collect::<Vec<_>>()
                        })
                        .collect::<Vec<_>>()
                })
                .collect::<Vec<_>>()
        })
        .collect()
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

/// The vertex positions of the `Mesh3D` in a chunk.
fn mesh_positions(chunk: &Chunk) -> Vec<[f32; 3]> {
    chunk
        .iter_component::<rerun::components::Position3D>(
            rerun::Mesh3D::descriptor_vertex_positions().component,
        )
        .flat_map(|batch| {
            batch
                .iter()
                .map(|p| [p.x(), p.y(), p.z()])
                .collect::<Vec<_>>()
        })
        .collect()
}

pub(crate) fn record_in_memory(scene: &Scene) -> (record::Summary, Contents) {
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

pub(crate) fn scene(text: &str) -> Scene {
    Scene::parse(text, "test", "test.toml").expect("a valid scene")
}

pub(crate) const FRICTION_SWEEP: &str = r#"
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
        "/sections/0/tractions/p",
        "/sections/0/tractions/q",
        "/sections/0/title",
        "/sections/0/colorbar/image",
        "/sections/0/colorbar/ticks",
        "/sections/0/colorbar/labels",
        "/sections/0/maximum",
        "/sections/0/maximum/label",
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
    // Steps count from 1 on the time panel, as in the titles.
    let expected: Vec<(i64, f64)> = (0..6).map(|k| (k + 1, 0.1 * k as f64)).collect();
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
    // Issue 23, item 8: the plots are the viewer's own (hover, zoom), against μ itself: every
    // step is also on the timeline `μ × 10`, which the time panel opens on.
    assert_eq!(contents.time_panel_timeline(), vec!["μ × 10".to_string()]);
    let against_mu = contents.scalars("/series/0/maximum", "μ × 10");
    let times: Vec<i64> = against_mu.iter().map(|(t, _)| *t).collect();
    assert_eq!(times, vec![0, 1, 2, 3, 4, 5]);
    assert_eq!(
        against_mu.iter().map(|(_, v)| *v).collect::<Vec<_>>(),
        maxima.iter().map(|(_, v)| *v).collect::<Vec<_>>()
    );
    let views = contents.view_names();
    // σvM marks its maximum only: the tab says "max", and no style of an unplotted minimum
    // is left to be a view error.
    for name in ["max / p0 vs μ", "depth vs μ"] {
        assert!(views.iter().any(|v| v == name), "{name} not in {views:?}");
    }
    assert!(!contents.paths().contains(&"/series/0/minimum"));
    assert!(
        !contents.paths().iter().any(|p| p.starts_with("/charts")),
        "raster charts left: {:?}",
        contents.paths()
    );
    // The title row follows the step (the first label of each row), with the traction legend.
    let titles = contents.labels("/sections/0/title");
    assert!(titles[0].starts_with("step 1 of 6: μ = 0"), "{titles:?}");
    let last = titles
        .iter()
        .rposition(|t| t.starts_with("step "))
        .expect("a title");
    assert!(
        titles[last].starts_with("step 6 of 6: μ = 0.5"),
        "{titles:?}"
    );
    assert!(
        titles[last + 1].starts_with("p: peak 1.00 p0"),
        "{titles:?}"
    );
    assert!(
        titles[last + 2].starts_with("q: largest |q| 0.500 p0"),
        "{titles:?}"
    );
    // The parameter once in each title, however the subtitle writes it.
    for title in titles.iter().filter(|t| t.starts_with("step ")) {
        assert_eq!(title.matches("μ = ").count(), 1, "{title}");
    }
    // The colour bar: nice ticks from 0, with the decimals of the tick step, and the caption
    // with the unit.
    let bar = contents.labels("/sections/0/colorbar/labels");
    assert_eq!(bar.first().map(String::as_str), Some("0.0"), "{bar:?}");
    assert!(contents.paths().contains(&"/sections/0/border"));
    assert_eq!(bar.last().map(String::as_str), Some("σvM / p0"), "{bar:?}");
    // The layout: the section view's area, the 2-D chart views, the panels collapsed.
    assert_eq!(contents.layout_paths("/VisualBounds2D").len(), 1);
    for panel in [
        "/blueprint_panel",
        "/selection_panel",
        "/time_panel",
        "/viewport",
    ] {
        assert!(
            contents.layout.contains_key(panel),
            "{panel}: {:?}",
            contents.layout.keys()
        );
    }
}

/// Issue 23, item 8: each step is also logged at its swept value, on a timeline whose name
/// gives the unit of its integers; the coarsest power of ten that holds the values exactly,
/// else one that puts a hundred units between the closest two.
#[test]
fn the_swept_value_has_a_timeline_of_its_own_in_a_stated_unit() {
    let moving = "format = 1\n[contact]\nkind = \"line\"\n[figure]\nquantity = \"sxz\"\nx = [-3.0, 3.0]\nz = [0.0, 2.0]\n[sweep]\nparameter = \"position\"\nvalues = [-2.0, -0.8660254037844386, 0.0, 0.8660254037844386, 2.0]\n";
    let ball = "format = 1\n[contact]\nkind = \"point\"\nload = \"100 N\"\n[contact.body1]\nradius = \"flat\"\nmaterial = \"steel\"\n[contact.body2]\nradius = \"6.35 mm\"\nmaterial = \"steel\"\n[sweep]\nparameter = \"load\"\nvalues = [\"50 N\", \"100 N\", \"800 N\"]\n";
    // (scene, the timeline's name and values, if any)
    type Expected<'a> = Option<(&'a str, Vec<i64>)>;
    let cases: [(&str, Expected); 6] = [
        (FRICTION_SWEEP, Some(("μ × 10", vec![0, 1, 2, 3, 4, 5]))),
        (SMALL_SWEEP, Some(("μ × 10", vec![0, 3]))),
        (ROUGH_SWEEP, Some(("W (mN)", vec![50, 200, 500]))),
        (ball, Some(("W (N)", vec![50, 100, 800]))),
        (
            moving,
            Some(("x0/a × 1000", vec![-2000, -866, 0, 866, 2000])),
        ),
        // Péclet numbers spanning decades: charts on logarithmic axes instead.
        (SPEED_SWEEP, None),
    ];
    for (text, expected) in cases {
        let got = record::value_timeline(&scene(text)).map(|v| (v.name, v.values));
        let expected = expected.map(|(name, values)| (name.to_string(), values));
        assert_eq!(got, expected, "{text}");
    }
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
    // The histories' views name the point (labelled on the map) and the unit of the stresses.
    let views = contents.view_names();
    for name in ["point 0 / p0", "point 1 / p0"] {
        assert!(views.iter().any(|v| v == name), "{name} not in {views:?}");
    }
    // Issue 23, item 5: each point also records the principal shear τ1 and σvM.
    let tau1 = contents.scalars("/history/0/point1/tau1", "position");
    let von_mises = contents.scalars("/history/0/point1/von_mises", "position");
    for (((_, t), (_, v)), x0) in tau1.iter().zip(&von_mises).zip(positions) {
        let s = line_hertz::stress_over_p0(1.0 - x0, 0.25, 0.0, 0.3);
        assert!((t - s.principal_shear_xz()).abs() < 1e-12);
        assert!((v - s.von_mises()).abs() < 1e-12);
    }
    // Signed: both extremes are marked and plotted, the negative lobe as much as the
    // positive one.
    let minima = contents.scalars("/series/0/minimum", "position");
    let maxima = contents.scalars("/series/0/maximum", "position");
    assert_eq!(minima.len(), 5);
    assert!(minima.iter().all(|(_, v)| *v < 0.0), "{minima:?}");
    assert!(maxima.iter().all(|(_, v)| *v > 0.0), "{maxima:?}");
    assert!(contents.labels("/sections/0/minimum/label")[0].starts_with("min τxz = −"));
}

#[test]
fn an_extreme_of_no_size_is_not_marked() {
    // With the load's centre at x0 = −3.5a the positive lobe of τxz lies behind it, outside
    // the map (x ≥ −3a): what the map holds of it is a small fraction of the colour range,
    // and only the negative lobe is marked. At x0 = 0 both lobes are.
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
values = [-3.5, 0.0]
"#;
    let (_, contents) = record_in_memory(&scene(text));
    let maxima = contents.labels("/sections/0/maximum/label");
    let minima = contents.labels("/sections/0/minimum/label");
    assert_eq!(minima.len(), 2, "{minima:?}");
    assert_eq!(maxima.len(), 1, "{maxima:?}");
    assert!(maxima[0].starts_with("max τxz = 0.2"), "{maxima:?}");
    // The series still has both steps.
    assert_eq!(contents.scalars("/series/0/maximum", "position").len(), 2);
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
    assert!(summary.volume_triangles > 1000, "{summary:?}");
    for path in [
        "/volume",
        "/volume/iso/0",
        "/volume/iso/3",
        "/volume/contact",
        "/volume/contact/patch",
        "/volume/maximum",
    ] {
        assert!(contents.paths().contains(&path), "{path} missing");
    }
    // The shells fill the half box behind y = 0 (the cut shows how they nest), under the
    // surface.
    for m in 0..4 {
        let vertices = mesh_positions(&contents.chunks[&format!("/volume/iso/{m}")][0]);
        assert!(!vertices.is_empty(), "level {m}");
        assert!(vertices
            .iter()
            .all(|p| p[1] <= 0.0 && p[2] >= 0.0 && p[2] <= 2.0));
    }
    // Levels at 50 % to 90 % of the largest: the innermost shell encloses the maximum, on the
    // axis at z = 0.48a (Johnson 1985, §3.4(b)), and is small.
    let inner = mesh_positions(&contents.chunks["/volume/iso/3"][0]);
    let (lo, hi) = inner
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), p| {
            (a.min(p[2]), b.max(p[2]))
        });
    assert!(lo < 0.48 && hi > 0.48 && hi - lo < 0.8, "{lo}..{hi}");
    let at = positions_3d(&contents.chunks["/volume/maximum"][0]);
    assert_eq!(at.len(), 1);
    assert!(at[0][0].abs() < 1e-6 && at[0][1].abs() < 1e-6, "{at:?}");
    assert!((at[0][2] - 0.5).abs() < 0.06, "{at:?}");
    // Issue 23, item 6: one maximum, one position: the report's refined one (Johnson's 0.48a),
    // not the grid's sample; its label sits above the surface.
    let reported = stressfield::study::assess::scene_maxima(&scene(text))
        .maxima
        .expect("maxima")
        .von_mises;
    assert!(
        (f64::from(at[0][2]) - reported.z_over_a).abs() < 1e-6,
        "{at:?} against {reported:?}"
    );
    let label = positions_3d(&contents.chunks["/volume/maximum/label"][0]);
    assert!(label.len() == 1 && label[0][2] < 0.0, "{label:?}");
    // The 3-D view opens looking at the patch from above (z < 0: z points into the body).
    let eye = contents.layout_paths("/EyeControls3D");
    assert_eq!(eye.len(), 1, "{:?}", contents.layout.keys());
    let position = contents.layout[eye[0]][0]
        .iter_component::<rerun::components::Position3D>(
            rerun::external::re_sdk_types::blueprint::archetypes::EyeControls3D::descriptor_position()
                .component,
        )
        .flat_map(|b| b.iter().map(|p| [p.x(), p.y(), p.z()]).collect::<Vec<_>>())
        .collect::<Vec<_>>();
    assert!(position.len() == 1 && position[0][2] < 0.0, "{position:?}");
    // A single step: no plots (they would be empty), no time panel.
    assert!(contents.paths().iter().all(|p| !p.starts_with("/charts")));
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
    // The file carries its viewer layout, which opens at the first step.
    assert!(contents.blueprints >= 1);
    assert_eq!(contents.play_state(), vec!["Paused"]);
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
        let speed_sweep = scene
            .sweep
            .as_ref()
            .is_some_and(|s| s.parameter == SweepParameter::Peclet);
        // A rough contact's load sweep logs its pressure map at every load (and places it
        // once, statically); a speed sweep its surface temperature at every speed.
        let entrainment_sweep = scene
            .sweep
            .as_ref()
            .is_some_and(|s| s.parameter == SweepParameter::EntrainmentSpeed);
        if entrainment_sweep {
            // The EHL sheet and the charts at every speed.
            for entity in ["/sheet", "/charts/films", "/charts/stress"] {
                assert_eq!(
                    contents.rows_on(entity, "entrainment_speed"),
                    steps,
                    "{}: {entity}",
                    path.display()
                );
            }
        } else if speed_sweep {
            assert_eq!(
                contents.rows_on("/surface/field", "peclet"),
                steps,
                "{}",
                path.display()
            );
        } else if scene.contact.coating.is_some() {
            // A coated scene's section at every thickness, from its study.
            assert_eq!(
                contents.rows_on("/section/field", record::timeline(&scene)),
                steps,
                "{}",
                path.display()
            );
        } else if scene.contact.kind == stressfield::scene::ContactKind::Rough {
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
            // The title row names the step's parameter once (a friction sweep's subtitle
            // writes μ too).
            if let Some(sweep) = &scene.sweep {
                let name = sweep.describe(0, &scene);
                let name = name.split(" = ").next().expect("a name");
                for title in contents
                    .labels("/sections/0/title")
                    .iter()
                    .filter(|t| t.starts_with("step "))
                {
                    assert_eq!(
                        title.matches(&format!("{name} = ")).count(),
                        1,
                        "{}: {title}",
                        path.display()
                    );
                }
            }
        }
        recorded += 1;
    }
    assert!(recorded >= 4, "{recorded} recording scenes");
}

/// A small periodic rough contact with a load sweep.
pub(crate) const ROUGH_SWEEP: &str = r#"
format = 1
title = "rough sweep"
[contact]
kind = "rough"
load = "0.2 N"
periodic = true
[contact.body1]
material = "steel"
[contact.body2]
material = "steel"
[surface.generate]
samples = 32
spacing = "1 um"
hurst = 0.8
rolloff = "16 um"
cutoff = "2 um"
rms_slope = 0.1
seed = 3
[sweep]
parameter = "load"
values = ["0.05 N", "0.2 N", "0.5 N"]
"#;

#[test]
fn a_rough_load_sweep_has_map_views_with_colour_bars_and_charts_against_the_load() {
    let (summary, contents) = record_in_memory(&scene(ROUGH_SWEEP));
    assert_eq!(summary.steps, 3);
    for path in [
        "/sheet",
        "/topography/surface",
        "/contact/field",
        "/contact/border",
        "/contact/colorbar/image",
        "/contact/colorbar/labels",
        "/contact/title",
        "/contact/maximum/label",
        "/series/contact_fraction",
        "/series/spots",
        "/series/max_pressure_mpa",
        "/depth/field",
        "/depth/colorbar/labels",
        "/maps/0/field",
        "/maps/0/colorbar/labels",
    ] {
        assert!(
            contents.paths().contains(&path),
            "{path} missing from {:?}",
            contents.paths()
        );
    }
    // Issue 23, item 4: the main area's tabs have short names, so that all seven show: the
    // sheet's maps by what they show, not by their figure titles.
    let views = contents.view_names();
    for name in [
        "topography",
        "pressure",
        "σvM xz section",
        "σvM at depth",
        "figure",
    ] {
        assert!(views.iter().any(|v| v == name), "{name} not in {views:?}");
    }
    assert!(
        views.iter().all(|v| v.chars().count() <= 24),
        "a tab name too long for its tab: {views:?}"
    );
    // The pressure map at every load, its title following the load.
    assert_eq!(contents.rows_on("/contact/field", "load"), 3);
    // Issue 23, item 8: native plots against the load itself, on the timeline `W (mN)` that
    // the time panel opens on.
    assert_eq!(contents.time_panel_timeline(), vec!["W (mN)".to_string()]);
    for path in [
        "/series/contact_fraction",
        "/series/spots",
        "/series/max_pressure_mpa",
    ] {
        let times: Vec<i64> = contents
            .scalars(path, "W (mN)")
            .iter()
            .map(|(t, _)| *t)
            .collect();
        assert_eq!(times, vec![50, 200, 500], "{path}");
    }
    assert_eq!(contents.rows_on("/contact/field", "W (mN)"), 3);
    for name in ["peak p (MPa) vs W", "A/A0 vs W", "spots vs W"] {
        assert!(views.iter().any(|v| v == name), "{name} not in {views:?}");
    }
    let titles = contents.labels("/contact/title");
    assert_eq!(titles.len(), 4, "{titles:?}");
    for (k, load) in ["0.05", "0.2", "0.5"].iter().enumerate() {
        assert!(
            titles[k].starts_with(&format!("step {} of 3: W = {load} N: ", k + 1)),
            "{titles:?}"
        );
    }
    // On the timeline `depth` the load's views are not empty: one row each, at its start and
    // on that timeline only, the last load with a title that says so.
    for path in ["/contact/field", "/contact/title"] {
        assert_eq!(contents.times_on(path, "depth", "load"), vec![1], "{path}");
    }
    assert!(
        titles[3].starts_with("step 3 of 3: W = 0.5 N: ")
            && titles[3]
                .ends_with("(the last load: the timeline \"load\" steps through the loads)"),
        "{titles:?}"
    );
    assert_eq!(
        contents
            .labels("/contact/colorbar/labels")
            .last()
            .map(String::as_str),
        Some("p (MPa)")
    );
    // The labelled maximum is the step's largest pressure, in MPa.
    let largest = contents.scalars("/series/max_pressure_mpa", "load");
    let labels = contents.labels("/contact/maximum/label");
    assert_eq!(labels.len(), 4, "{labels:?}");
    assert_eq!(
        labels[3], labels[2],
        "the last load on the timeline `depth`"
    );
    for (label, (_, value)) in labels.iter().zip(&largest) {
        let shown: f64 = label
            .strip_prefix("max p = ")
            .and_then(|rest| rest.split(' ').next())
            .and_then(|number| number.parse().ok())
            .unwrap_or_else(|| panic!("{label}"));
        assert!(((shown - value) / value).abs() < 5e-3, "{label} vs {value}");
        assert!(
            label.contains(" MPa at x = ") && label.ends_with(" µm"),
            "{label}"
        );
    }
    // More load, more contact.
    let fraction = contents.scalars("/series/contact_fraction", "load");
    assert!(fraction.windows(2).all(|w| w[1].1 > w[0].1), "{fraction:?}");
    // The depth steps are on their own timeline; on the timeline `load` (which the recording
    // opens on) the depth view holds the layer of the report's maximum from the first load
    // on, not nothing.
    let layers = contents.rows_on("/depth/field", "depth");
    assert!(layers >= 2);
    assert_eq!(
        contents.times_on("/depth/field", "depth", "load").len(),
        layers
    );
    assert_eq!(contents.times_on("/depth/field", "load", "depth"), vec![1]);
    let depth_titles = contents.labels("/depth/title");
    assert!(depth_titles[0].starts_with("layer 1 of "));
    let preview = depth_titles.last().expect("a title");
    assert!(
        preview.starts_with("layer ")
            && preview.ends_with(": the report's largest σvM (the timeline \"depth\" steps down)"),
        "{preview}"
    );
    let value = |label: &String| -> f64 {
        label
            .strip_prefix("max σvM = ")
            .and_then(|rest| rest.split(' ').next())
            .and_then(|number| number.parse().ok())
            .unwrap_or_else(|| panic!("{label}"))
    };
    let maxima = contents.labels("/depth/maximum/label");
    assert_eq!(maxima.len(), layers + 1, "{maxima:?}");
    // Within the report's refinement (a sixteenth of a cell) of the largest of all layers.
    let deepest_largest = maxima[..layers].iter().map(value).fold(0.0, f64::max);
    assert!(
        value(&maxima[layers]) >= deepest_largest / 1.005,
        "{maxima:?}"
    );
    let layer: usize = preview["layer ".len()..]
        .split(' ')
        .next()
        .and_then(|n| n.parse().ok())
        .expect("a layer number");
    assert_eq!(maxima[layer - 1], maxima[layers], "{preview}");
    // Every 2-D map view opens on its frame.
    assert!(contents.layout_paths("/VisualBounds2D").len() >= 3);
}

/// A steel ball sliding on a steel flat, its speed swept over two decades of the flat's Péclet
/// number in three steps (Blok's partition).
const SPEED_SWEEP: &str = r#"
format = 1
title = "speed sweep"
[contact]
kind = "point"
load = "50 N"
friction = 0.1
[contact.body1]
radius = "flat"
material = "steel"
[contact.body2]
radius = "10 mm"
material = "steel"
[thermal]
speed = "1 m/s"
partition = "blok"
[sweep]
parameter = "peclet"
from = 0.1
to = 10.0
steps = 3
"#;

#[test]
fn a_speed_sweep_records_the_temperature_sweeping_back_on_the_peclet_timeline() {
    let scene = scene(SPEED_SWEEP);
    assert_eq!(record::timeline(&scene), "peclet");
    let (summary, contents) = record_in_memory(&scene);
    assert_eq!(summary.steps, 3);
    for path in [
        "/description",
        "/log",
        "/surface/field",
        "/surface/border",
        "/surface/outline",
        "/surface/title",
        "/surface/maximum/label",
        "/surface/colorbar/image",
        "/surface/colorbar/labels",
        "/section/field",
        "/section/surface",
        "/section/title",
        "/section/colorbar/labels",
        "/charts/max_temperature",
        "/charts/max_position",
        "/charts/share",
        "/series/peclet",
        "/series/sliding_speed_m_per_s",
        "/series/max_temperature_rise_k",
        "/series/mean_temperature_rise_k",
        "/series/max_x_over_a",
        "/series/body1_share",
    ] {
        assert!(
            contents.paths().contains(&path),
            "{path} missing from {:?}",
            contents.paths()
        );
    }
    // Three steps on the timeline `peclet`, spaced geometrically; each view, its colour bar
    // (a range per step) and each chart once per step.
    let peclets = contents.scalars("/series/peclet", "peclet");
    for ((t, pe), (k, expected)) in peclets.iter().zip([(1, 0.1), (2, 1.0), (3, 10.0)]) {
        assert_eq!(*t, k);
        assert!((pe / expected - 1.0).abs() < 1e-12, "{peclets:?}");
    }
    for path in [
        "/surface/field",
        "/section/field",
        "/surface/colorbar/labels",
        "/section/colorbar/labels",
        "/charts/max_temperature",
        "/charts/max_position",
        "/charts/share",
    ] {
        assert_eq!(contents.rows_on(path, "peclet"), 3, "{path}");
    }
    // The speed scales with Pe; the flux with it, so the maximum grows (faster than √V,
    // slower than V); the hottest point moves back behind the centre; the flat, over which
    // the contact moves, takes more of the heat as it moves faster (Blok).
    let speeds = contents.scalars("/series/sliding_speed_m_per_s", "peclet");
    assert!(
        (speeds[2].1 / speeds[0].1 - 100.0).abs() < 1e-9,
        "{speeds:?}"
    );
    let maxima = contents.scalars("/series/max_temperature_rise_k", "peclet");
    let means = contents.scalars("/series/mean_temperature_rise_k", "peclet");
    for k in 0..2 {
        let ratio = maxima[k + 1].1 / maxima[k].1;
        assert!(ratio > 10f64.sqrt() && ratio < 10.0, "{maxima:?}");
        assert!(means[k].1 < maxima[k].1, "{means:?} {maxima:?}");
    }
    let x = contents.scalars("/series/max_x_over_a", "peclet");
    assert!(x[2].1 < x[1].1 && x[1].1 < x[0].1 && x[1].1 < 0.0, "{x:?}");
    let share = contents.scalars("/series/body1_share", "peclet");
    assert!(share[0].1 > 0.5 && share[2].1 > share[0].1, "{share:?}");
    // The title names the step's Pe and V once, and the step's colour range; the labelled
    // maximum is the series' in K.
    let titles = contents.labels("/surface/title");
    assert_eq!(titles.len(), 3, "{titles:?}");
    assert!(
        titles[0].starts_with("step 1 of 3: Pe = 0.1 (V = ")
            && titles[0].ends_with(" m/s); body 1 takes 51.4 % of the heat"),
        "{titles:?}"
    );
    // The section's title gives the step's colour range: 0 to its maximum rounded up.
    let section_titles = contents.labels("/section/title");
    assert_eq!(section_titles.len(), 3, "{section_titles:?}");
    for (title, (_, max)) in section_titles.iter().zip(&maxima) {
        let top: f64 = title
            .split("; colours 0 to ")
            .nth(1)
            .and_then(|rest| rest.strip_suffix(" K (this step's range)"))
            .and_then(|number| number.parse().ok())
            .unwrap_or_else(|| panic!("{title}"));
        assert!(top >= *max && top < 1.1 * max, "{title} vs {max}");
    }
    for title in &titles {
        assert_eq!(title.matches("Pe = ").count(), 1, "{title}");
    }
    let labels = contents.labels("/surface/maximum/label");
    for (label, (_, value)) in labels.iter().zip(&maxima) {
        let shown: f64 = label
            .strip_prefix("max ΔT = ")
            .and_then(|rest| rest.split(' ').next())
            .and_then(|number| number.parse().ok())
            .unwrap_or_else(|| panic!("{label}"));
        assert!(((shown - value) / value).abs() < 5e-3, "{label} vs {value}");
    }
    // A colour bar per step, captioned with the unit, its top tick below the step's maximum
    // rounded up.
    let bar = contents.labels("/surface/colorbar/labels");
    assert_eq!(bar.iter().filter(|l| *l == "ΔT (K)").count(), 3, "{bar:?}");
    // The layout: the two maps framed, the charts, opening at the first step.
    let views = contents.view_names();
    for name in [
        "body 1's surface temperature rise (K) against Pe",
        "xz section through the contact's centre (K), depth down",
        "max ΔT vs Pe",
        "hottest x vs Pe",
        "share vs Pe",
    ] {
        assert!(views.iter().any(|v| v == name), "{name} not in {views:?}");
    }
    assert_eq!(contents.layout_paths("/VisualBounds2D").len(), 2);
}

/// Case: a speed sweep the scene cannot make is refused before anything is written, with the
/// key and the fix.
#[test]
fn a_bad_speed_sweep_names_the_key_and_leaves_no_file() {
    let rough = ROUGH_SWEEP
        .replace("periodic = true", "periodic = true\nfriction = 0.2")
        .replace(
            "[sweep]\nparameter = \"load\"\nvalues = [\"0.05 N\", \"0.2 N\", \"0.5 N\"]",
            "[thermal]\nspeed = \"1 m/s\"\n[sweep]\nparameter = \"peclet\"\nvalues = [1.0, 10.0]",
        );
    assert!(rough.contains("peclet"));
    let no_thermal =
        SPEED_SWEEP.replace("[thermal]\nspeed = \"1 m/s\"\npartition = \"blok\"\n", "");
    let gears = std::fs::read_to_string("scenes/gear_pitch_point.toml").expect("gear scene")
        + "\n[sweep]\nparameter = \"peclet\"\nfrom = 0.1\nto = 10.0\nsteps = 3\n";
    let cases: [(String, &[&str]); 6] = [
        (gears, &["sweep.parameter", "path of contact"]),
        (
            rough,
            &[
                "sweep.parameter",
                "not for a rough contact",
                "stressfield thermal",
            ],
        ),
        (no_thermal, &["sweep.parameter", "add [thermal]"]),
        (
            SPEED_SWEEP.replace("from = 0.1", "from = 0.0"),
            &[
                "sweep.from",
                "geometrically",
                "three decades",
                "from = 0.1, to = 100",
            ],
        ),
        (
            SPEED_SWEEP.replace("to = 10.0", "to = 500.0"),
            &[
                "sweep.to",
                "Pe = 500 is beyond what the sweep's grid resolves",
                "106.7",
            ],
        ),
        (
            SPEED_SWEEP.replace("from = 0.1\nto = 10.0\nsteps = 3", "values = [1.0, 0.0]"),
            &["sweep.values[1]", "at least 0.001"],
        ),
    ];
    for (text, fragments) in cases {
        let (dir, path) = scene_file(&text);
        let out = dir.path().join("out");
        std::fs::create_dir(&out).expect("out/");
        let output = stressfield()
            .args(["record", path.to_str().expect("utf8"), "-o"])
            .arg(out.join("case.rrd"))
            .output()
            .expect("the binary runs");
        assert!(!output.status.success(), "{text}");
        let message = stderr_of(&output);
        for fragment in fragments {
            assert!(
                message.contains(fragment),
                "`{fragment}` not in:\n{message}"
            );
        }
        assert!(message.contains("hint:"), "{message}");
        assert!(
            names_in(&out).is_empty(),
            "left behind: {:?}",
            names_in(&out)
        );
    }
}

// --- The command line: where recordings go, and what is left behind (issue 13, cases 8, 11
// and 15; issue 14: streaming).

fn stressfield() -> std::process::Command {
    let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_stressfield"));
    command
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("CI", "true");
    command
}

fn stderr_of(output: &std::process::Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Writes `text` as `case.toml` into a fresh directory.
fn scene_file(text: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let path = dir.path().join("case.toml");
    std::fs::write(&path, text).expect("scene written");
    (dir, path)
}

fn names_in(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("listed")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A sweep long enough to be interrupted (hundreds of steps at a fine resolution).
const LONG_SWEEP: &str = "format = 1\n[contact]\nkind = \"line\"\n[figure]\nquantity = \"von_mises\"\nresolution = 801\n[sweep]\nparameter = \"friction\"\nfrom = 0.0\nto = 0.5\nsteps = 400\n";

/// Case 8: Ctrl-C (SIGINT) or `kill` (SIGTERM) during `record` removes the temporary file
/// and reports the interruption with the shell's status (128 + the signal).
#[cfg(unix)]
#[test]
fn an_interrupted_record_leaves_no_temporary_file() {
    for (signal, status) in [("-INT", 130), ("-TERM", 143)] {
        let (dir, scene) = scene_file(LONG_SWEEP);
        let out = dir.path().join("out");
        std::fs::create_dir(&out).expect("out/");
        let child = stressfield()
            .args(["record", scene.to_str().expect("utf8"), "-o"])
            .arg(out.join("long.rrd"))
            .stdout(std::process::Stdio::null())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .expect("the binary runs");
        // Wait until the recording's temporary file exists, then interrupt.
        let started = std::time::Instant::now();
        while names_in(&out).is_empty() {
            assert!(
                started.elapsed() < std::time::Duration::from_secs(60),
                "no temporary file appeared"
            );
            std::thread::sleep(std::time::Duration::from_millis(10));
        }
        assert!(
            names_in(&out)[0].ends_with(".rrd.part"),
            "{:?}",
            names_in(&out)
        );
        let killed = std::process::Command::new("kill")
            .args([signal, &child.id().to_string()])
            .status()
            .expect("kill runs");
        assert!(killed.success());
        let output = child.wait_with_output().expect("ends");
        assert_eq!(output.status.code(), Some(status), "{}", stderr_of(&output));
        assert!(
            stderr_of(&output).contains("interrupted"),
            "{}",
            stderr_of(&output)
        );
        assert!(
            names_in(&out).is_empty(),
            "left behind: {:?}",
            names_in(&out)
        );
    }
}

/// A small sweep for the output tests.
const SMALL_SWEEP: &str = "format = 1\n[contact]\nkind = \"line\"\nfriction = 0.2\n[figure]\nquantity = \"von_mises\"\nresolution = 81\n[sweep]\nparameter = \"friction\"\nvalues = [0.0, 0.3]\n";

/// Case 11: a full disk (a link to /dev/full) is reported with the path and the system's
/// reason, not as a Rerun thread that "shut down prematurely".
#[cfg(unix)]
#[test]
fn a_full_disk_names_the_file_and_the_system_error() {
    if !std::path::Path::new("/dev/full").exists() {
        return;
    }
    let (dir, scene) = scene_file(SMALL_SWEEP);
    let link = dir.path().join("full.rrd");
    std::os::unix::fs::symlink("/dev/full", &link).expect("symlink");
    let output = stressfield()
        .args(["record", scene.to_str().expect("utf8"), "-o"])
        .arg(&link)
        .output()
        .expect("runs");
    let text = stderr_of(&output);
    assert!(!output.status.success(), "{text}");
    assert!(
        text.contains(&format!("cannot write {}", link.display())),
        "{text}"
    );
    assert!(text.contains("No space left on device"), "{text}");
    assert!(!text.contains("prematurely"), "{text}");
    // The link is still a link, and nothing else was left.
    assert!(std::fs::symlink_metadata(&link)
        .expect("exists")
        .file_type()
        .is_symlink());
    assert_eq!(names_in(dir.path()), vec!["case.toml", "full.rrd"]);
}

/// Case 15: a link is followed (its target replaced, the link kept); a FIFO is written
/// through, as a shell's `>` would; a directory is refused. Nothing is renamed over them.
#[cfg(unix)]
#[test]
fn links_fifos_and_directories_are_never_replaced() {
    use std::os::unix::fs::FileTypeExt;
    let (dir, scene) = scene_file(SMALL_SWEEP);
    let scene = scene.to_str().expect("utf8").to_string();
    let run = |target: &std::path::Path| {
        stressfield()
            .args(["record", &scene, "-o"])
            .arg(target)
            .output()
            .expect("runs")
    };
    // A link to a regular file: the file gets the recording, the link stays a link.
    let target = dir.path().join("target.rrd");
    std::fs::write(&target, b"old").expect("written");
    let link = dir.path().join("link.rrd");
    std::os::unix::fs::symlink(&target, &link).expect("symlink");
    let output = run(&link);
    assert!(output.status.success(), "{}", stderr_of(&output));
    assert!(std::fs::symlink_metadata(&link)
        .expect("exists")
        .file_type()
        .is_symlink());
    assert!(std::fs::read(&target).expect("read").starts_with(b"RRF2"));
    // A FIFO: read on the other side, still a FIFO afterwards.
    let fifo = dir.path().join("pipe.rrd");
    let made = std::process::Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read(fifo).expect("read the FIFO"))
    };
    let output = run(&fifo);
    assert!(output.status.success(), "{}", stderr_of(&output));
    let bytes = reader.join().expect("the reader ends");
    assert!(bytes.starts_with(b"RRF2") && bytes.len() > 1000);
    assert!(std::fs::symlink_metadata(&fifo)
        .expect("exists")
        .file_type()
        .is_fifo());
    // A directory is refused.
    let output = run(dir.path());
    assert!(!output.status.success());
    assert!(
        stderr_of(&output).contains("it is a directory"),
        "{}",
        stderr_of(&output)
    );
    assert_eq!(
        names_in(dir.path()),
        vec!["case.toml", "link.rrd", "pipe.rrd", "target.rrd"]
    );
}

/// `-o -`: the recording on standard output, a complete stream a viewer reads (`| rerun -`).
#[test]
fn a_recording_streams_to_standard_output() {
    let (_dir, scene) = scene_file(SMALL_SWEEP);
    let output = stressfield()
        .args(["record", scene.to_str().expect("utf8"), "-o", "-"])
        .output()
        .expect("runs");
    assert!(output.status.success(), "{}", stderr_of(&output));
    assert!(
        stderr_of(&output).contains("to standard output"),
        "{}",
        stderr_of(&output)
    );
    let messages: Vec<LogMsg> = DecoderApp::decode_lazy(std::io::Cursor::new(output.stdout))
        .map(|message| message.expect("a valid message"))
        .collect();
    let contents = Contents::from_messages(messages);
    assert_eq!(contents.scalars("/series/0/maximum", "friction").len(), 2);
    assert!(contents.blueprints >= 1);
    // Piped into a viewer, the time cursor follows the steps as they arrive.
    assert_eq!(contents.play_state(), vec!["Following"]);
}

/// A stand-in for a Rerun viewer's gRPC endpoint (`MessageProxyService/WriteMessages`, the
/// call `--connect` makes), enough of HTTP/2 (RFC 9113) and gRPC to take one client-streaming
/// call: it answers the connection's settings and pings, keeps the flow-control windows open,
/// collects the call's DATA frames, and once the client ends the call replies `200` with
/// `grpc-status: 0`. Returns the gRPC messages' bodies (protobuf `WriteMessagesRequest`s).
fn stand_in_viewer(listener: std::net::TcpListener) -> Vec<Vec<u8>> {
    use std::io::{Read, Write};
    let (mut socket, _) = listener.accept().expect("the client connects");
    socket
        .set_read_timeout(Some(std::time::Duration::from_secs(120)))
        .expect("timeout");
    let mut preface = [0u8; 24];
    socket.read_exact(&mut preface).expect("the preface");
    assert_eq!(&preface, b"PRI * HTTP/2.0\r\n\r\nSM\r\n\r\n", "not HTTP/2");
    let frame = |kind: u8, flags: u8, stream: u32, payload: &[u8]| {
        let mut bytes = (payload.len() as u32).to_be_bytes()[1..].to_vec();
        bytes.extend([kind, flags]);
        bytes.extend(stream.to_be_bytes());
        bytes.extend(payload);
        bytes
    };
    let window_update = |stream: u32, increment: u32| frame(8, 0, stream, &increment.to_be_bytes());
    // SETTINGS: INITIAL_WINDOW_SIZE (4) = 2^31 - 1; and the connection's window opened as far.
    let mut settings = 4u16.to_be_bytes().to_vec();
    settings.extend(0x7fff_ffffu32.to_be_bytes());
    socket.write_all(&frame(4, 0, 0, &settings)).expect("write");
    socket
        .write_all(&window_update(0, 0x7fff_ffff - 65_535))
        .expect("write");
    let mut body = Vec::new();
    loop {
        let mut header = [0u8; 9];
        match socket.read_exact(&mut header) {
            Ok(()) => {}
            // The client hung up: the call is over.
            Err(e) if e.kind() == std::io::ErrorKind::UnexpectedEof => break,
            Err(e) => panic!("reading a frame: {e}"),
        }
        let length = u32::from_be_bytes([0, header[0], header[1], header[2]]) as usize;
        let (kind, flags) = (header[3], header[4]);
        let stream = u32::from_be_bytes([header[5], header[6], header[7], header[8]]) & 0x7fff_ffff;
        let mut payload = vec![0u8; length];
        socket.read_exact(&mut payload).expect("a frame's payload");
        match kind {
            // DATA, possibly padded (flag 0x8): the call's bytes; END_STREAM (0x1) ends it.
            0 => {
                let data = if flags & 0x8 != 0 {
                    let pad = usize::from(payload[0]);
                    &payload[1..payload.len() - pad]
                } else {
                    &payload[..]
                };
                body.extend_from_slice(data);
                if length > 0 {
                    socket
                        .write_all(&window_update(stream, length as u32))
                        .expect("write");
                }
                if flags & 0x1 != 0 {
                    // HEADERS (END_HEADERS): `:status: 200` (static table entry 8), then
                    // `content-type: application/grpc` (literal, name at static index 31).
                    let mut block = vec![0x88, 0x0f, 0x10, 16];
                    block.extend(b"application/grpc");
                    socket
                        .write_all(&frame(1, 0x4, stream, &block))
                        .expect("write");
                    // Trailers (END_HEADERS | END_STREAM): `grpc-status: 0` (literal, new name).
                    let mut trailers = vec![0x00, 11];
                    trailers.extend(b"grpc-status");
                    trailers.extend([1, b'0']);
                    socket
                        .write_all(&frame(1, 0x5, stream, &trailers))
                        .expect("write");
                }
            }
            // SETTINGS (not an ACK): acknowledge.
            4 if flags & 0x1 == 0 => socket.write_all(&frame(4, 0x1, 0, &[])).expect("write"),
            // PING (not an ACK): answer.
            6 if flags & 0x1 == 0 => socket
                .write_all(&frame(6, 0x1, 0, &payload))
                .expect("write"),
            // GOAWAY: the client is done.
            7 => break,
            // HEADERS, CONTINUATION, WINDOW_UPDATE, RST_STREAM, acknowledgements: nothing to do.
            _ => {}
        }
    }
    // gRPC messages: a compression flag (0), a big-endian length, the protobuf.
    let mut messages = Vec::new();
    let mut rest = &body[..];
    while !rest.is_empty() {
        assert_eq!(rest[0], 0, "an uncompressed gRPC message");
        let length = u32::from_be_bytes([rest[1], rest[2], rest[3], rest[4]]) as usize;
        messages.push(rest[5..5 + length].to_vec());
        rest = &rest[5 + length..];
    }
    messages
}

/// A protobuf varint at the start of `bytes`, and the bytes after it.
fn varint(bytes: &[u8]) -> (u64, &[u8]) {
    let mut value = 0u64;
    for (i, &byte) in bytes.iter().enumerate() {
        value |= u64::from(byte & 0x7f) << (7 * i);
        if byte & 0x80 == 0 {
            return (value, &bytes[i + 1..]);
        }
    }
    panic!("a truncated varint");
}

/// The one length-delimited field of a protobuf message: its number and its bytes.
fn only_field(bytes: &[u8]) -> (u64, &[u8]) {
    let (key, rest) = varint(bytes);
    assert_eq!(key & 7, 2, "a length-delimited field");
    let (length, rest) = varint(rest);
    assert_eq!(rest.len() as u64, length, "one field");
    (key >> 3, rest)
}

/// The messages of a gRPC stream as an .rrd stream: each `WriteMessagesRequest { log_msg:
/// LogMsg { oneof msg } }` becomes the frame `MessageHeader { kind, len }` + the oneof's
/// message, the kinds numbered as the oneof's fields (1 store info, 2 Arrow data, 3 blueprint
/// activation), after a stream header.
fn rrd_of_grpc(messages: &[Vec<u8>]) -> Vec<u8> {
    use rerun::external::re_log_encoding::{
        CrateVersion, Encodable, EncodingOptions, MessageHeader, MessageKind, StreamHeader,
        RRD_FOURCC,
    };
    let mut out = Vec::new();
    StreamHeader {
        fourcc: RRD_FOURCC,
        version: CrateVersion::LOCAL.to_bytes(),
        options: EncodingOptions::PROTOBUF_COMPRESSED,
    }
    .to_rrd_bytes(&mut out)
    .expect("a header");
    for message in messages {
        let (field, log_msg) = only_field(message);
        assert_eq!(field, 1, "WriteMessagesRequest.log_msg");
        let (kind, inner) = only_field(log_msg);
        let kind = match kind {
            1 => MessageKind::SetStoreInfo,
            2 => MessageKind::ArrowMsg,
            3 => MessageKind::BlueprintActivationCommand,
            other => panic!("LogMsg field {other}"),
        };
        MessageHeader {
            kind,
            len: inner.len() as u64,
        }
        .to_rrd_bytes(&mut out)
        .expect("a frame header");
        out.extend_from_slice(inner);
    }
    out
}

/// `--connect URL`: the recording streams to the viewer at that address (here a stand-in
/// listening on a free port), which receives the whole recording with its layout.
#[test]
fn a_recording_streams_to_a_viewer_at_the_given_address() {
    let (_dir, scene) = scene_file(SMALL_SWEEP);
    let listener = std::net::TcpListener::bind("127.0.0.1:0").expect("a free port");
    let url = format!(
        "rerun+http://127.0.0.1:{}/proxy",
        listener.local_addr().expect("address").port()
    );
    let viewer = std::thread::spawn(move || stand_in_viewer(listener));
    let output = stressfield()
        .args(["record", scene.to_str().expect("utf8"), "--connect", &url])
        .output()
        .expect("runs");
    let text = stderr_of(&output);
    assert!(output.status.success(), "{text}");
    assert!(
        text.contains(&format!("to the Rerun viewer at {url}")),
        "{text}"
    );
    let messages = viewer.join().expect("the stand-in ends");
    let rrd = rrd_of_grpc(&messages);
    let decoded: Vec<LogMsg> = DecoderApp::decode_lazy(std::io::Cursor::new(rrd))
        .map(|message| message.expect("a valid message"))
        .collect();
    let contents = Contents::from_messages(decoded);
    assert!(contents
        .application_ids
        .iter()
        .all(|id| id == APPLICATION_ID));
    assert_eq!(contents.scalars("/series/0/maximum", "friction").len(), 2);
    assert!(contents.paths().contains(&"/sections/0/colorbar/labels"));
    assert!(contents.blueprints >= 1, "the layout is sent too");
    assert_eq!(contents.play_state(), vec!["Following"]);
}

/// `--connect URL` with no viewer there: a clear error naming the address, after the SDK's
/// connection timeout.
#[test]
fn connecting_to_no_viewer_fails_clearly() {
    let (_dir, scene) = scene_file(SMALL_SWEEP);
    let url = "rerun+http://127.0.0.1:1/proxy";
    let output = stressfield()
        .args(["record", scene.to_str().expect("utf8"), "--connect", url])
        .output()
        .expect("runs");
    let text = stderr_of(&output);
    assert!(!output.status.success(), "{text}");
    assert!(text.contains(&format!("cannot stream to {url}")), "{text}");
    assert!(text.contains("--spawn"), "{text}");
}

/// `--spawn` with no `rerun` on the PATH: a clear error saying how to install the viewer.
/// (Skipped when a viewer already listens on the default port: `--spawn` would stream to it.)
#[test]
fn spawning_without_a_viewer_installed_fails_clearly() {
    let default = std::net::SocketAddr::from(([127, 0, 0, 1], 9876));
    if std::net::TcpStream::connect_timeout(&default, std::time::Duration::from_millis(500)).is_ok()
    {
        eprintln!("a viewer listens on {default}: --spawn would use it; not tested here");
        return;
    }
    let (dir, scene) = scene_file(SMALL_SWEEP);
    let output = stressfield()
        .args(["record", scene.to_str().expect("utf8"), "--spawn"])
        .env("PATH", dir.path())
        .output()
        .expect("runs");
    let text = stderr_of(&output);
    assert!(!output.status.success(), "{text}");
    assert!(text.contains("cannot start a Rerun viewer"), "{text}");
    assert!(text.contains("pip install"), "{text}");
}

/// Every text of `component` in `chunks`, in order.
fn texts<'a>(
    chunks: impl IntoIterator<Item = &'a Chunk>,
    component: rerun::ComponentIdentifier,
) -> Vec<String> {
    chunks
        .into_iter()
        .flat_map(|chunk| {
            chunk
                .iter_component::<rerun::components::Text>(component)
                .flat_map(|batch| {
                    batch
                        .iter()
                        .map(|t| t.as_str().to_string())
                        .collect::<Vec<_>>()
                })
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Issue 23, item 10: a periodic contact whose maximum lies under the map's corner cell is
/// recorded as the sheet draws it, rolled by whole cells so the maximum is at the centre: the
/// depth map spans x from −64 to 64 µm (128 cells of 1 µm), not 0 to 128 µm.
#[test]
fn a_periodic_contact_on_the_seam_is_recorded_centred_on_its_maximum() {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests")
        .join("data")
        .join("rough_worn_on_seam.toml");
    let scene = Scene::load(&path).expect("a valid scene");
    let (_, contents) = record_in_memory(&scene);
    let border = strip_points_2d(&contents, "/depth/border");
    assert!(!border.is_empty(), "{:?}", contents.paths());
    let (lo, hi) = border
        .iter()
        .fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), p| {
            (a.min(p[0]), b.max(p[0]))
        });
    assert!(
        (lo + 64.0).abs() < 1e-3 && (hi - 64.0).abs() < 1e-3,
        "depth map from x = {lo} to {hi} µm"
    );
    // The labelled maximum is the report's, in its cell at the centre.
    let labels = contents.labels("/depth/maximum/label");
    assert!(
        labels
            .iter()
            .any(|l| l == "max σvM = 1660 MPa at x = 0.500 µm, y = 0.500 µm"),
        "{labels:?}"
    );
}
