//! Kernel benchmarks: dense geometric product, a motor applied to a point, decomposition,
//! typed rotors and motors.
//! Run with `cargo bench -p cga`; figures go to docs/performance.md.

use cga::{Multivector, Similarity};
use criterion::{criterion_group, criterion_main, Criterion};
// Criterion 0.5's own `black_box` is a volatile copy: for a 256-byte multivector that costs
// tens of nanoseconds per operand, more than some of the operations measured here. Inputs
// are hidden behind references for the same reason: hiding a multivector by value copies
// it through memory on every iteration (≈ 15 ns for a motor), which callers do not pay.
use glam::{DQuat, DVec3};
use std::hint::black_box;

fn dense(seed: f64) -> Multivector {
    Multivector::from_coefficients(std::array::from_fn(|i| (seed + i as f64 * 0.731).sin()))
}

fn motor() -> Multivector {
    Similarity {
        translation: DVec3::new(0.3, -1.2, 2.5),
        rotation: DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7),
        scale: 1.5,
    }
    .to_versor()
    .expect("valid similarity")
}

/// Keeps a result alive without criterion's volatile copy of it (see the `use` above).
fn discard<T>(value: T) {
    black_box(value);
}

fn kernels(c: &mut Criterion) {
    let (a, b) = (dense(0.1), dense(2.3));
    c.bench_function("geometric product (dense)", |bench| {
        bench.iter(|| discard(*black_box(&a) * *black_box(&b)))
    });
    c.bench_function("geometric product (blade table, reference)", |bench| {
        bench.iter(|| {
            discard(
                black_box(&a).product_by_table(black_box(&b), cga::blade::ProductKind::Geometric),
            )
        })
    });
    let m = motor();
    let p = DVec3::new(0.5, 0.25, -1.0);
    c.bench_function("motor applied to a point", |bench| {
        bench.iter(|| discard(black_box(&m).transform_point(black_box(p))))
    });
    c.bench_function("point map construction (PointMap::new)", |bench| {
        bench.iter(|| discard(cga::PointMap::new(black_box(&m))))
    });
    let map = cga::PointMap::new(&m).expect("even versor");
    c.bench_function("motor applied to a point (precomputed PointMap)", |bench| {
        bench.iter(|| discard(black_box(&map).transform_point(black_box(p))))
    });
    c.bench_function("motor applied to a point (dense sandwich)", |bench| {
        bench.iter(|| {
            let m = *black_box(&m);
            discard((m * Multivector::up(black_box(p)) * m.reverse()).down())
        })
    });
    c.bench_function("decomposition T·R·D", |bench| {
        bench.iter(|| discard(Similarity::from_versor(black_box(&m))))
    });
    c.bench_function("inverse (general, linear system)", |bench| {
        bench.iter(|| discard(black_box(&a).inverse()))
    });
}

fn typed(c: &mut Criterion) {
    use cga::{Motor, Rotor};
    let q1 = DQuat::from_axis_angle(DVec3::new(1.0, 2.0, 3.0).normalize(), 0.7);
    let q2 = DQuat::from_axis_angle(DVec3::new(-1.0, 0.5, 0.2).normalize(), 1.9);
    let (r1, r2) = (Rotor::from_quat(q1), Rotor::from_quat(q2));
    let m1 = Motor::translator(DVec3::new(0.3, -1.2, 2.5)) * Motor::from(r1);
    let m2 = Motor::translator(DVec3::new(-4.0, 0.1, 0.7)) * Motor::from(r2);
    let (d1, d2) = (Multivector::from(m1), Multivector::from(m2));
    c.bench_function("rotor × rotor (typed)", |bench| {
        bench.iter(|| discard(*black_box(&r1) * *black_box(&r2)))
    });
    c.bench_function("motor × motor (typed)", |bench| {
        bench.iter(|| discard(*black_box(&m1) * *black_box(&m2)))
    });
    c.bench_function("motor × motor (even × even kernel)", |bench| {
        bench.iter(|| discard(black_box(&d1).geometric_even_even(black_box(&d2))))
    });
    c.bench_function("motor × motor (dense)", |bench| {
        bench.iter(|| discard(*black_box(&d1) * *black_box(&d2)))
    });
    c.bench_function("glam quaternion product (reference)", |bench| {
        bench.iter(|| discard(*black_box(&q1) * *black_box(&q2)))
    });
    let p = DVec3::new(0.5, 0.25, -1.0);
    c.bench_function("motor applied to a point (typed)", |bench| {
        bench.iter(|| discard(black_box(&m1).transform_point(black_box(p))))
    });
}

criterion_group!(benches, kernels, typed);
criterion_main!(benches);
