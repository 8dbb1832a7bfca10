//! Sliding Hertz sphere (closed form) in a 256 x 256 x 128 volume: all six stress components
//! and von Mises, stored as f32, sequential layers against the parallel evaluator.
//! Target (issue 3): at least 15 million points per second on two cores.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use stressfield::field::{self, Axis, Plane, Volume};
use stressfield::solution::Solution;
use stressfield::stress::Quantity;

const QUANTITIES: [Quantity; 7] = [
    Quantity::Sxx,
    Quantity::Syy,
    Quantity::Szz,
    Quantity::Syz,
    Quantity::Sxz,
    Quantity::Sxy,
    Quantity::VonMises,
];

fn sphere_volume(c: &mut Criterion) {
    let mut group = c.benchmark_group("sphere_hertz_volume");
    group.sample_size(10);
    let solution = Solution::SphereHertz {
        friction: 0.3,
        poisson: 0.3,
    };
    let volume = Volume {
        x: Axis::new(-2.0, 2.0, 256),
        y: Axis::new(-2.0, 2.0, 256),
        z: Axis::new(0.0, 2.0, 128),
    };
    group.throughput(Throughput::Elements(volume.points() as u64));
    group.bench_with_input(
        BenchmarkId::new("parallel_f32", "256x256x128"),
        &volume,
        |b, volume| {
            b.iter(|| field::evaluate_volume::<f32>(&solution, volume, &QUANTITIES, &|| {}))
        },
    );
    // One layer on the calling thread, for the scaling figure.
    let layer = Plane {
        section: field::Section::Xy { z: 0.5 },
        u: volume.x,
        v: volume.y,
    };
    group.throughput(Throughput::Elements(layer.points() as u64));
    group.bench_with_input(
        BenchmarkId::new("sequential_layer", "256x256"),
        &layer,
        |b, layer| b.iter(|| field::evaluate_sequential(&solution, layer, &QUANTITIES)),
    );
    group.finish();
}

criterion_group!(benches, sphere_volume);
criterion_main!(benches);
