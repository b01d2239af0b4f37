//! ThreeDWorld (TDW) export: an edit as the commands that replay it in TDW.
//!
//! TDW runs in Unity: left-handed, +Y up, metres, and its objects' pivot is the bottom
//! centre of their bounds — Shenlong's own pivot for box objects. The mapping is the Z
//! mirror of SPEC §1: a position `(x, y, z)` is sent as `(x, y, −z)`, a quaternion
//! `[x, y, z, w]` as `[−x, −y, z, w]` (the same rotation seen in the mirrored frame).
//!
//! | change | command |
//! |---|---|
//! | position | `{"$type": "teleport_object", "id", "position": {x, y, z}}` |
//! | rotation | `{"$type": "rotate_object_to", "id", "rotation": {x, y, z, w}}` |
//! | scale | `{"$type": "scale_object", "id", "scale_factor": {x, y, z}}` — TDW scales relative to the current scale, so the factor is new ÷ old |

use super::tidy;
use crate::scene::{Object, Scene, Shape};
use cga::Similarity;
use glam::{DQuat, DVec3};
use serde_json::{json, Value};

/// The commands that take each object of `before` to its pose in `after` (the same
/// objects, in the same order), for the objects that changed. `ids` are TDW object ids.
pub fn edit(before: &Scene, after: &Scene, ids: &[i64]) -> Vec<Value> {
    let mut commands = Vec::new();
    for ((a, b), &id) in before.objects.iter().zip(&after.objects).zip(ids) {
        let (pa, pb) = (pose(a), pose(b));
        if (pa.translation - pb.translation).length() > 1e-9 {
            commands.push(teleport(id, pb.translation));
        }
        if pa.rotation.dot(pb.rotation).abs() < 1.0 - 1e-12 {
            commands.push(rotate_to(id, pb.rotation));
        }
        if (pa.scale - pb.scale).abs() > 1e-12 {
            commands.push(scale(id, pb.scale / pa.scale));
        }
    }
    commands
}

/// Commands placing every object where the scene has it, for objects added to TDW at
/// scale 1.
pub fn place_all(scene: &Scene, ids: &[i64]) -> Vec<Value> {
    let mut commands = Vec::new();
    for (object, &id) in scene.objects.iter().zip(ids) {
        let p = pose(object);
        commands.push(teleport(id, p.translation));
        commands.push(rotate_to(id, p.rotation));
        if (p.scale - 1.0).abs() > 1e-12 {
            commands.push(scale(id, p.scale));
        }
    }
    commands
}

/// The pose TDW sees: the box pivot (bottom centre) for box objects; for meshes, the
/// bottom centre of their world box.
fn pose(object: &Object) -> Similarity {
    match object.shape {
        Shape::Box { .. } => object.similarity(),
        Shape::Points { .. } => {
            let s = object.similarity();
            Similarity {
                translation: object.world_aabb().bottom_center(),
                ..s
            }
        }
    }
}

/// A position in Unity's frame.
pub fn to_unity_position(p: DVec3) -> DVec3 {
    DVec3::new(p.x, p.y, -p.z)
}

/// A rotation in Unity's frame.
pub fn to_unity_rotation(q: DQuat) -> DQuat {
    DQuat::from_xyzw(-q.x, -q.y, q.z, q.w)
}

fn teleport(id: i64, position: DVec3) -> Value {
    let p = to_unity_position(position);
    json!({"$type": "teleport_object", "id": id, "position": {"x": tidy(p.x), "y": tidy(p.y), "z": tidy(p.z)}})
}

fn rotate_to(id: i64, rotation: DQuat) -> Value {
    let q = to_unity_rotation(rotation);
    json!({"$type": "rotate_object_to", "id": id, "rotation": {"x": tidy(q.x), "y": tidy(q.y), "z": tidy(q.z), "w": tidy(q.w)}})
}

fn scale(id: i64, factor: f64) -> Value {
    let f = tidy(factor);
    json!({"$type": "scale_object", "id": id, "scale_factor": {"x": f, "y": f, "z": f}})
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::format::procthor::unity_euler_to_quat;
    use cga::Multivector;

    fn scene() -> Scene {
        let mut s = Scene::new("t");
        s.push_box("a", [1.0; 3], [1.0, 0.0, 2.0]);
        s.objects.push(
            Object::new_box(
                "b",
                DVec3::ONE,
                DVec3::new(-1.0, 0.0, 0.0),
                DQuat::IDENTITY,
                2.0,
            )
            .unwrap(),
        );
        s
    }

    #[test]
    fn an_edit_becomes_the_commands_that_replay_it() {
        let before = scene();
        let mut after = before.clone();
        let m = Multivector::translator(DVec3::new(0.5, 0.0, 1.0))
            * Multivector::rotor(
                std::f64::consts::FRAC_PI_2,
                &Multivector::e3(),
                &Multivector::e1(),
            )
            .unwrap()
            * Multivector::dilator(1.5).unwrap();
        after.apply(0, &m, false).unwrap();
        let commands = edit(&before, &after, &[7, 8]);
        assert_eq!(commands.len(), 3, "only object 7 changed: {commands:?}");
        assert_eq!(
            commands[0],
            json!({"$type": "teleport_object", "id": 7, "position": {"x": 1.5, "y": 0.0, "z": -3.0}})
        );
        assert_eq!(commands[1]["$type"], "rotate_object_to");
        assert_eq!(
            commands[2],
            json!({"$type": "scale_object", "id": 7, "scale_factor": {"x": 1.5, "y": 1.5, "z": 1.5}})
        );
        // +90° about +Y here is Unity's Euler y = −90 (Unity turns +Z toward +X for +y).
        let r = &commands[1]["rotation"];
        let sent = DQuat::from_xyzw(
            r["x"].as_f64().unwrap(),
            r["y"].as_f64().unwrap(),
            r["z"].as_f64().unwrap(),
            r["w"].as_f64().unwrap(),
        );
        let unity_minus_90 = DQuat::from_rotation_y(-std::f64::consts::FRAC_PI_2);
        assert!(sent.dot(unity_minus_90).abs() > 1.0 - 1e-9, "{sent}");
    }

    #[test]
    fn mirroring_is_consistent_with_the_procthor_import() {
        // Unity Euler → our quaternion (import) → Unity quaternion (export) is Unity's own.
        for euler in [[0.0, 90.0, 0.0], [10.0, 200.0, -30.0]] {
            let ours = unity_euler_to_quat(euler);
            let back = to_unity_rotation(ours);
            let [x, y, z] = euler.map(f64::to_radians);
            let unity =
                DQuat::from_rotation_y(y) * DQuat::from_rotation_x(x) * DQuat::from_rotation_z(z);
            assert!(back.dot(unity).abs() > 1.0 - 1e-12, "{euler:?}");
        }
    }

    #[test]
    fn a_procthor_front_is_unitys_forward_after_export() {
        // ProcTHOR objects face local −Z here (Unity's +Z forward, mirrored). Whatever the
        // edit turned them by, the exported rotation turns Unity's forward onto the mirror
        // of the object's world front: TDW sees it face where Shenlong says it faces.
        for yaw in [0.0, 37.0, 90.0, 200.0, -135.0] {
            let mut s = Scene::new("t");
            let mut o = Object::new_box(
                "chair",
                DVec3::ONE,
                DVec3::ZERO,
                DQuat::from_rotation_y(f64::to_radians(yaw)),
                1.0,
            )
            .unwrap();
            o.front = DVec3::NEG_Z;
            s.objects.push(o);
            let command = &place_all(&s, &[1])[1];
            let r = &command["rotation"];
            let sent = DQuat::from_xyzw(
                r["x"].as_f64().unwrap(),
                r["y"].as_f64().unwrap(),
                r["z"].as_f64().unwrap(),
                r["w"].as_f64().unwrap(),
            );
            let unity_forward = sent * DVec3::Z;
            let ours = to_unity_position(s.objects[0].world_front());
            assert!(
                (unity_forward - ours).length() < 1e-6, // the export rounds to 1e-9
                "yaw {yaw}: {unity_forward} vs {ours}"
            );
        }
    }

    #[test]
    fn place_all_positions_every_object() {
        let commands = place_all(&scene(), &[1, 2]);
        assert_eq!(commands.len(), 5);
        assert_eq!(
            commands[4],
            json!({"$type": "scale_object", "id": 2, "scale_factor": {"x": 2.0, "y": 2.0, "z": 2.0}})
        );
    }
}
