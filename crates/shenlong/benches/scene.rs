//! Scene throughput on a large scene: read, edit and write a 10,000-object scene JSON.
//! Run with `cargo bench -p shenlong --bench scene`; figures go to docs/performance.md.

use cga::Multivector;
use criterion::{black_box, criterion_group, criterion_main, Criterion};
use glam::{DQuat, DVec3};
use shenlong::format::json;
use shenlong::scene::{Object, Scene};

/// 5,000 tables on a grid, each with an item resting on it: 10,000 objects.
pub fn large_scene(tables: usize) -> Scene {
    let mut scene = Scene::new("warehouse");
    let side = (tables as f64).sqrt().ceil() as usize;
    for i in 0..tables {
        let (x, z) = ((i % side) as f64 * 2.0, (i / side) as f64 * 2.0);
        let yaw = (i % 7) as f64 * 0.3;
        scene.objects.push(
            Object::new_box(
                format!("table {i}"),
                DVec3::new(1.2, 0.75, 0.8),
                DVec3::new(x, 0.0, z),
                DQuat::from_rotation_y(yaw),
                1.0,
            )
            .unwrap(),
        );
        scene.objects.push(
            Object::new_box(
                format!("item {i}"),
                DVec3::new(0.2, 0.3, 0.2),
                DVec3::new(x, 0.75, z),
                DQuat::IDENTITY,
                1.0,
            )
            .unwrap(),
        );
    }
    scene
}

fn bench(c: &mut Criterion) {
    let text = json::write(&large_scene(5_000), None);
    let mut group = c.benchmark_group("scene JSON, 10,000 objects");
    group.sample_size(20);
    group.bench_function("read (parse, validate, find supports)", |b| {
        b.iter(|| json::read(black_box(&text), "warehouse").unwrap())
    });
    let loaded = json::read(&text, "warehouse").unwrap();
    let m = Multivector::translator(DVec3::new(0.5, 0.0, 0.0));
    group.bench_function("apply one edit (with carrying)", |b| {
        b.iter_batched(
            || loaded.scene.clone(),
            |mut scene| scene.apply(black_box(2_500), &m, true).unwrap(),
            criterion::BatchSize::LargeInput,
        )
    });
    group.bench_function("write", |b| {
        b.iter(|| json::write(black_box(&loaded.scene), Some(&loaded.document)))
    });
    group.bench_function("read + apply + write", |b| {
        b.iter(|| {
            let mut l = json::read(black_box(&text), "warehouse").unwrap();
            l.scene.apply(2_500, &m, true).unwrap();
            json::write(&l.scene, Some(&l.document))
        })
    });
    group.finish();
}

fn collisions(c: &mut Criterion) {
    let mut group = c.benchmark_group("collision resolution");
    group.sample_size(20);
    for tables in [50, 5_000] {
        let text = json::write(&large_scene(tables), None);
        let scene = json::read(&text, "warehouse").unwrap().scene;
        let before = scene.world_aabbs();
        // Push table 0 (with its item) 1.2 m along +x: into table 1 (2 m away).
        let mut edited = scene.clone();
        edited
            .apply(0, &Multivector::translator(DVec3::new(1.2, 0.0, 0.0)), true)
            .unwrap();
        let options = shenlong::collide::ResolveOptions::default();
        let check = shenlong::collide::resolve(
            &mut edited.clone(),
            &before,
            &[0],
            &shenlong::ground::kind::is_floor_bound,
            &options,
        )
        .unwrap();
        assert_eq!(
            check.adjustments.len(),
            1,
            "the benchmark must exercise a real search"
        );
        group.bench_function(
            format!("{} objects: detect + resolve one collision", 2 * tables),
            |b| {
                b.iter_batched(
                    || edited.clone(),
                    |mut s| {
                        shenlong::collide::resolve(
                            &mut s,
                            black_box(&before),
                            &[0],
                            &shenlong::ground::kind::is_floor_bound,
                            &options,
                        )
                        .unwrap()
                    },
                    criterion::BatchSize::LargeInput,
                )
            },
        );
        // The same push with shapes read (`scene::form`): the pushed object a chair, its
        // seat and back checked against every box it meets, tables on legs looked up.
        let mut chaired_edited = edited.clone();
        chaired_edited.objects[0].name = "chair 0".into();
        group.bench_function(
            format!(
                "{} objects: detect + resolve one collision, shapes",
                2 * tables
            ),
            |b| {
                b.iter_batched(
                    || chaired_edited.clone(),
                    |mut s| {
                        shenlong::collide::resolve(
                            &mut s,
                            black_box(&before),
                            &[0],
                            &shenlong::pipeline::Lexical::new(&[]),
                            &options,
                        )
                        .unwrap()
                    },
                    criterion::BatchSize::LargeInput,
                )
            },
        );
        group.bench_function(
            format!("{} objects: read the scene JSON", 2 * tables),
            |b| b.iter(|| json::read(black_box(&text), "warehouse").unwrap()),
        );
    }
    group.finish();
}

fn offline(c: &mut Criterion) {
    use shenlong::pipeline::{template, Translator};
    let scene = shenlong::examples::build("workshop").unwrap();
    let translator = shenlong::offline::OfflineTranslator::new();
    let mut group = c.benchmark_group("offline translator");
    for (name, instruction) in [
        ("simple", "move the 'stool' 2 units to the left"),
        ("compositional", "rotate the 'stool' by 90 degrees and move it 0.5 m to the right"),
        ("fuzzy", "put the 'orange bottle' on top of the 'tool table'"),
        ("hard", "stack the 'cardboard box' on the 'tool table' and the 'orange bottle' on the 'cardboard box'"),
    ] {
        let templated = template(instruction, &scene).unwrap();
        group.bench_function(format!("{name}: reply and evaluation"), |b| {
            b.iter(|| translator.translate(black_box(&templated), &scene).unwrap())
        });
    }
    group.finish();
}

/// A furnished scene of `rooms × 10` objects: per room a sofa, two armchairs, a coffee
/// table with a mug on it, a floor lamp, a bookshelf, two chairs and a plant, named as
/// ProcTHOR names them (`chair`, `chair 2`, …).
fn furnished(rooms: usize) -> Scene {
    let kinds: [(&str, [f64; 3], [f64; 2], f64); 10] = [
        ("sofa", [2.0, 0.85, 0.9], [0.0, -1.5], 0.0),
        ("armchair", [0.9, 0.9, 0.85], [-1.8, 0.0], 0.0),
        ("armchair", [0.9, 0.9, 0.85], [1.8, 0.0], 0.0),
        ("coffee table", [1.1, 0.45, 0.6], [0.0, 0.0], 0.0),
        ("mug", [0.09, 0.1, 0.09], [0.2, 0.0], 0.45),
        ("floor lamp", [0.4, 1.6, 0.4], [-2.5, -1.8], 0.0),
        ("bookshelf", [0.9, 1.8, 0.35], [2.5, -1.8], 0.0),
        ("chair", [0.45, 0.95, 0.5], [-0.6, 1.6], 0.0),
        ("chair", [0.45, 0.95, 0.5], [0.6, 1.6], 0.0),
        ("house plant", [0.5, 1.2, 0.5], [2.5, 1.8], 0.0),
    ];
    let mut scene = Scene::new("house");
    let mut counts = std::collections::HashMap::new();
    let side = (rooms as f64).sqrt().ceil() as usize;
    for r in 0..rooms {
        let (ox, oz) = ((r % side) as f64 * 7.0, (r / side) as f64 * 6.0);
        for (name, size, [x, z], y) in kinds {
            let n = counts.entry(name).or_insert(0);
            *n += 1;
            let name = if *n == 1 {
                name.to_string()
            } else {
                format!("{name} {n}")
            };
            scene.objects.push(
                Object::new_box(
                    name,
                    DVec3::from(size),
                    DVec3::new(ox + x, y, oz + z),
                    DQuat::IDENTITY,
                    1.0,
                )
                .unwrap(),
            );
        }
    }
    scene.detect_supports();
    scene
}

fn grounding(c: &mut Criterion) {
    use shenlong::ground::Grounder;
    let mut group = c.benchmark_group("grounding");
    for rooms in [10, 1_000] {
        let scene = furnished(rooms);
        let grounder = Grounder::new(&scene);
        group.bench_function(
            format!("{} objects: build the name index", scene.objects.len()),
            |b| b.iter(|| Grounder::new(black_box(&scene))),
        );
        // On the 100-object scene each phrase grounds; on the 10,000-object one "the couch"
        // and "the mug nearest …" fit a thousand objects and are refused with the
        // candidates named — both paths are what a user meets.
        for (what, instruction) in [
            ("a synonym", "move the couch 30 cm to the left"),
            (
                "a numbered name and a typo",
                "put armchair 7 next to the bokshelf 7",
            ),
            (
                "a relation",
                "put the mug nearest the floor lamp on the sofa",
            ),
        ] {
            group.bench_function(format!("{} objects: {what}", scene.objects.len()), |b| {
                b.iter(|| grounder.ground(black_box(instruction), &scene))
            });
        }
    }
    group.finish();
}

/// A grid of unit boxes 1.5 m apart, as `bench/big_scenes.py` writes it.
fn grid_text(count: usize) -> (String, String) {
    let side = (count as f64).sqrt().ceil() as usize;
    let mut text = String::from("{\"name\": \"grid\", \"objects\": [\n");
    for i in 0..count {
        let (x, z) = ((i % side) as f64 * 1.5, (i / side) as f64 * 1.5);
        if i > 0 {
            text.push_str(",\n");
        }
        text.push_str(&format!(
            "{{\"name\": \"box-{i}\", \"size\": [1, 1, 1], \"position\": [{x}, 0, {z}]}}"
        ));
    }
    text.push_str("\n]}\n");
    let middle = ((side / 2) * side + side / 2).min(count - 1);
    (text, format!("box-{middle}"))
}

/// One edit whose object lands on its neighbour and is moved to a free place, at 1,000 to
/// 1,000,000 objects, in phases (the whole process is `bench/big_scenes.py`).
fn big_scenes(c: &mut Criterion) {
    use shenlong::pipeline::{edit_with, EditOptions};
    let translator = shenlong::offline::OfflineTranslator::new();
    let options = EditOptions::new(true, Some(shenlong::collide::ResolveOptions::default()));
    let mut group = c.benchmark_group("big scenes");
    group.sample_size(10);
    for count in [1_000, 10_000, 100_000, 1_000_000] {
        let (text, name) = grid_text(count);
        let instruction = format!("move the '{name}' 1.5 m to the right");
        group.bench_function(format!("{count} objects: read"), |b| {
            b.iter(|| json::read(black_box(&text), "grid").unwrap())
        });
        let loaded = json::read(&text, "grid").unwrap();
        group.bench_function(format!("{count} objects: name index"), |b| {
            b.iter(|| shenlong::ground::Grounder::new(black_box(&loaded.scene)))
        });
        let grounder = shenlong::ground::Grounder::new(&loaded.scene);
        group.bench_function(format!("{count} objects: edit with a collision"), |b| {
            b.iter_batched(
                || loaded.scene.clone(),
                |mut scene| {
                    let e = edit_with(&mut scene, &grounder, &instruction, &translator, &options)
                        .unwrap();
                    assert_eq!(e.report.collisions_resolved.len(), 1);
                    scene
                },
                criterion::BatchSize::LargeInput,
            )
        });
        let mut edited = loaded.scene.clone();
        edit_with(&mut edited, &grounder, &instruction, &translator, &options).unwrap();
        group.bench_function(format!("{count} objects: write"), |b| {
            b.iter(|| json::write(black_box(&edited), Some(&loaded.document)))
        });
    }
    group.finish();
}

/// A desk as a mesh: a top 4 cm thick on four legs, each box `cells` × `cells` quads a
/// face (12·cells² triangles a box).
fn desk_mesh(cells: u32) -> (Vec<DVec3>, Vec<[u32; 3]>) {
    let mut parts = vec![(DVec3::new(0.0, 0.72, 0.0), DVec3::new(1.2, 0.76, 0.7))];
    for (x, z) in [(0.0, 0.0), (1.15, 0.0), (0.0, 0.65), (1.15, 0.65)] {
        parts.push((DVec3::new(x, 0.0, z), DVec3::new(x + 0.05, 0.72, z + 0.05)));
    }
    let (mut v, mut t) = (Vec::new(), Vec::new());
    for (lo, hi) in parts {
        let size = hi - lo;
        // Each face of the box as a grid of cells × cells quads.
        for axis in 0..3 {
            for side in [0.0, 1.0] {
                let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
                let base = v.len() as u32;
                for i in 0..=cells {
                    for j in 0..=cells {
                        let mut p = lo;
                        p[axis] += side * size[axis];
                        p[u] += size[u] * f64::from(i) / f64::from(cells);
                        p[w] += size[w] * f64::from(j) / f64::from(cells);
                        v.push(p);
                    }
                }
                for i in 0..cells {
                    for j in 0..cells {
                        let k = base + i * (cells + 1) + j;
                        t.push([k, k + 1, k + cells + 2]);
                        t.push([k, k + cells + 2, k + cells + 1]);
                    }
                }
            }
        }
    }
    (v, t)
}

/// Reading what a mesh shows of the room under or in it (`scene::mesh::measure`), for a
/// plain desk and a finely divided one, and reading a real glTF file (2CylinderEngine.glb,
/// 29 meshes, from ../shared/data when present) with it.
fn meshes(c: &mut Criterion) {
    let mut group = c.benchmark_group("mesh shapes");
    group.sample_size(20);
    for cells in [1, 64] {
        let (v, t) = desk_mesh(cells);
        group.bench_function(format!("measure a desk of {} triangles", t.len()), |b| {
            b.iter(|| shenlong::scene::mesh::measure(black_box(&v), black_box(&t)))
        });
    }
    let engine = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data/gltf/2CylinderEngine.glb");
    if engine.is_file() {
        let options = shenlong::format::ReadOptions {
            units: Some(shenlong::format::facts::Units::Millimetres),
            ..Default::default()
        };
        group.bench_function("read 2CylinderEngine.glb (29 meshes measured)", |b| {
            b.iter(|| shenlong::format::SceneFile::load_with(black_box(&engine), &options).unwrap())
        });
    } else {
        eprintln!("skipping 2CylinderEngine.glb: ../shared/data is absent");
    }
    group.finish();
}

criterion_group!(benches, bench, collisions, offline, grounding, big_scenes, meshes);
criterion_main!(benches);
