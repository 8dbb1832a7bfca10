//! Volume plasticity under a rough map (issue 51): the 128² target of the issue, "a 128²
//! rough map with volume plasticity within one minute". The map: a rough steel ball (R = 2 mm,
//! self-affine roughness Sq 0.05 µm, Hurst 0.8, seed 3) on 128² samples of 0.5 µm, pressed on
//! a steel flat by 0.5 N (the elastic peak pressure 4.1 Y) with Y = 1 GPa, perfectly plastic;
//! 16 layers down to twice the largest spot's radius, 4 load and 2 unload steps, tolerance
//! 1e-6; isolated (padded) and periodic. One sample is one whole `stressfield plastic` study
//! (the elastic pre-solves included).

use criterion::{criterion_group, criterion_main, Criterion};
use stressfield::scene::Scene;
use stressfield::study::plastic;

const SCENE: &str = r#"format = 1
[contact]
kind = "rough"
load = "0.5 N"
periodic = PERIODIC
[contact.body1]
material = "steel"
[contact.body2]
material = "steel"
[surface.generate]
samples = 128
spacing = "0.5 um"
hurst = 0.8
rolloff = "32 um"
cutoff = "2 um"
rms_height = "0.05 um"
sphere_radius = "2 mm"
seed = 3
[plasticity]
yield_strength = "1 GPa"
steps = 4
unload_steps = 2
depth_cells = 16
"#;

fn plastic_rough(c: &mut Criterion) {
    let mut group = c.benchmark_group("plastic_rough");
    group.sample_size(10);
    for (name, periodic) in [
        ("isolated_128x128x16", "false"),
        ("periodic_128x128x16", "true"),
    ] {
        let text = SCENE.replace("PERIODIC", periodic);
        let scene = Scene::parse(&text, name, "bench.toml").expect("scene");
        group.bench_function(name, |b| {
            b.iter(|| plastic::study(&scene, &mut |_| {}).expect("solves"))
        });
    }
    group.finish();
}

criterion_group!(benches, plastic_rough);
criterion_main!(benches);
