//! A scene as a list of plain records — each object's name, pose, box and support — for
//! programs: the MCP server's `list_objects` and the Python package's `Scene.objects()`.

use super::{Scene, Shape};
use crate::number::tidy;
use glam::DVec3;
use serde::Serialize;

/// The scene, as `list_objects` answers.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct SceneListing {
    /// The scene's name.
    pub scene: String,
    /// The room (floor at `min[1]`, walls at the x and z limits), if it has one.
    pub bounds: Option<Bounds>,
    /// The objects, in file order.
    pub objects: Vec<ObjectListing>,
}

/// An axis-aligned box, in metres (+Y up, +X right, +Z towards the viewer).
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct Bounds {
    /// The low corner.
    pub min: [f64; 3],
    /// The high corner.
    pub max: [f64; 3],
}

/// One object.
#[derive(Clone, Debug, Serialize)]
#[cfg_attr(feature = "schema", derive(schemars::JsonSchema))]
pub struct ObjectListing {
    /// Its name (unique, compared without case).
    pub name: String,
    /// Its pose's position: the bottom centre of its box (for a mesh, its origin).
    pub position: [f64; 3],
    /// Its box's size along its own axes (for a mesh, its world box's).
    pub size: [f64; 3],
    /// Its rotation as a unit quaternion `[x, y, z, w]`.
    pub rotation: [f64; 4],
    /// Its uniform scale.
    pub scale: f64,
    /// Its world bounding box.
    pub world_box: Bounds,
    /// The direction it faces, in the world.
    pub front: [f64; 3],
    /// The object it rests on, if any (it is carried when that one moves).
    pub rests_on: Option<String>,
}

fn r(v: DVec3) -> [f64; 3] {
    v.to_array().map(tidy)
}

/// Lists the scene's objects, numbers rounded as the scene files write them.
#[must_use]
pub fn listing(scene: &Scene) -> SceneListing {
    SceneListing {
        scene: scene.name.clone(),
        bounds: scene.bounds.map(|b| Bounds {
            min: r(b.min),
            max: r(b.max),
        }),
        objects: scene
            .objects
            .iter()
            .map(|o| {
                let pose = o.similarity();
                let world = o.world_aabb();
                let size = match &o.shape {
                    Shape::Box { size } => *size,
                    Shape::Points { .. } => world.size(),
                };
                ObjectListing {
                    name: o.name.clone(),
                    position: r(pose.translation),
                    size: r(size),
                    rotation: pose.rotation.to_array().map(tidy),
                    scale: tidy(pose.scale),
                    world_box: Bounds {
                        min: r(world.min),
                        max: r(world.max),
                    },
                    front: r(o.world_front()),
                    rests_on: o.support.map(|s| scene.objects[s].name.clone()),
                }
            })
            .collect(),
    }
}
