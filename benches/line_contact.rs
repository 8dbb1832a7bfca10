//! Line-contact closed form on a 1024 x 1024 grid with von Mises: sequential and parallel.
//! Target (issue 2): at least 1e8 points per second on two cores.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use stressfield::field::{self, Axis, Plane};
use stressfield::solution::Solution;
use stressfield::stress::Quantity;

fn line_contact(c: &mut Criterion) {
    let mut group = c.benchmark_group("line_hertz_von_mises");
    group.sample_size(20);
    let solution = Solution::LineHertz {
        friction: 0.2,
        poisson: 0.3,
    };
    for n in [256usize, 1024] {
        let plane = Plane::xz(Axis::new(-3.0, 3.0, n), Axis::new(0.0, 3.0, n));
        group.throughput(Throughput::Elements((n * n) as u64));
        group.bench_with_input(
            BenchmarkId::new("sequential", format!("{n}x{n}")),
            &plane,
            |b, plane| {
                b.iter(|| field::evaluate_sequential(&solution, plane, &[Quantity::VonMises]))
            },
        );
        group.bench_with_input(
            BenchmarkId::new("parallel", format!("{n}x{n}")),
            &plane,
            |b, plane| b.iter(|| field::evaluate(&solution, plane, &[Quantity::VonMises], &|| {})),
        );
    }
    group.finish();
}

criterion_group!(benches, line_contact);
criterion_main!(benches);
