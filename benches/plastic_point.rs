//! Volume plasticity under a rigid ball (issue 51's speed target, "at most half of EPIC's time
//! on a 64×64×32 and a 128×128×64 volume"): the problem of
//! `scenes/plastic_rigid_ball_on_flat.toml` (a rigid ball, R = 10 mm, on a steel flat with
//! Y = 1 GPa, perfectly plastic, pressed to Hertz's p0 = 2.5 Y), two load steps, no
//! unloading, tolerance 1e-6, the lateral grid ±2 a_H and the layers down to 2 a_H, on
//! 32×32×16 and 64×64×32 cells. One sample is one whole `stressfield plastic` study. The
//! same problems in Tamaas's EPICSolver, one after the other in one run:
//! `benches/peers/plastic_side_by_side.py` (docs/plasticity.md, "Against Tamaas's
//! EPICSolver").

use criterion::{criterion_group, criterion_main, Criterion};
use stressfield::scene::Scene;
use stressfield::study::plastic;

const SCENE: &str = r#"format = 1
[contact]
kind = "point"
load = "151.62 N"
[contact.body1]
radius = "flat"
material = "steel"
[contact.body2]
radius = "10 mm"
material = "rigid"
[plasticity]
yield_strength = "1 GPa"
hardening_modulus = "0 GPa"
unload = false
steps = 2
tolerance = 1e-6
grid_cells = CELLS
depth_cells = LAYERS
extent_over_a = 2.0
depth_over_a = 2.0
"#;

fn plastic_point(c: &mut Criterion) {
    let mut group = c.benchmark_group("plastic_point");
    group.sample_size(10);
    for (cells, layers) in [(32, 16), (64, 32)] {
        let name = format!("rigid_ball_2.5Y_{cells}x{cells}x{layers}");
        let text = SCENE
            .replace("CELLS", &cells.to_string())
            .replace("LAYERS", &layers.to_string());
        let scene = Scene::parse(&text, &name, "bench.toml").expect("scene");
        group.bench_function(&name, |b| {
            b.iter(|| plastic::study(&scene, &mut |_| {}).expect("solves"))
        });
    }
    group.finish();
}

criterion_group!(benches, plastic_point);
criterion_main!(benches);
