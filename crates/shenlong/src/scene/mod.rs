//! The scene model: named objects with a shape and a pose kept as a CGA versor.
//!
//! An object's pose is the versor `V = T·R·D` that maps its local shape into the world
//! (SPEC §2–§3). A transformation `M` from an instruction acts in the frame centred at the
//! object's pivot, with the world's axes: `V' = T(p)·M·T(p)⁻¹·V`. Objects resting on the
//! moved one are carried along with the same world motion. Every applied motion is
//! recorded in world form, so undoing it is exact.

mod support;

use crate::geometry::Aabb;
use cga::{CgaError, Multivector, Similarity};
use glam::{DQuat, DVec3};

pub use support::SUPPORT_GAP;

/// The largest coordinate (and box extent) Shenlong keeps exact, in metres: positions and
/// sizes beyond it are refused on reading, and an edit that would go beyond it is refused.
pub const MAX_COORDINATE: f64 = 1e6;
/// The smallest uniform scale accepted.
pub const MIN_SCALE: f64 = 1e-6;
/// The largest uniform scale accepted.
pub const MAX_SCALE: f64 = 1e6;

impl Scene {
    /// Whether applying `m` about the pivot of object `index` (carrying what rests on it
    /// with `carry`) keeps every pose it moves within [`MAX_COORDINATE`] and the scale
    /// limits; `Err` says which object would leave them and how.
    ///
    /// # Errors
    /// The first object the motion would take out of the limits.
    pub fn check_motion(&self, index: usize, m: &Multivector, carry: bool) -> Result<(), String> {
        let Ok(step) = Similarity::from_versor(m) else {
            return Err(
                "the transformation is not a translation, rotation and uniform scale".into(),
            );
        };
        if !step.translation.is_finite()
            || step.translation.abs().max_element() > 2.0 * MAX_COORDINATE
        {
            return Err(format!(
                "the move of {:.3e} m is beyond the {MAX_COORDINATE:.0e} m Shenlong keeps exact",
                step.translation.length()
            ));
        }
        if !(step.scale.is_finite() && step.scale >= MIN_SCALE && step.scale <= MAX_SCALE) {
            return Err(format!(
                "the scale {:.3e} is outside [{MIN_SCALE:.0e}, {MAX_SCALE:.0e}]",
                step.scale
            ));
        }
        let world = self.world_motion(index, m);
        let mut targets = vec![index];
        if carry {
            targets.extend(self.carried_by(index));
        }
        for i in targets {
            let o = &self.objects[i];
            let pose = world * *o.pose();
            let within = Similarity::from_versor(&pose).is_ok_and(|s| {
                s.translation.is_finite()
                    && s.translation.abs().max_element() <= MAX_COORDINATE
                    && s.scale >= MIN_SCALE
                    && s.scale <= MAX_SCALE
            });
            if !within {
                return Err(format!(
                    "the edit would take '{}' beyond the limits Shenlong keeps exact (|position| ≤ {MAX_COORDINATE:.0e} m, scale in [{MIN_SCALE:.0e}, {MAX_SCALE:.0e}])",
                    o.name
                ));
            }
        }
        Ok(())
    }
}

/// A scene: a name, optional room bounds and the objects.
#[derive(Clone, Debug)]
pub struct Scene {
    /// The scene's name.
    pub name: String,
    /// The room: floor at `min.y`, walls at the x and z limits. Without it the floor is
    /// y = 0 and there are no walls.
    pub bounds: Option<Aabb>,
    /// The objects, in file order.
    pub objects: Vec<Object>,
}

/// What an object's local shape is.
#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// A box with its pivot at the bottom centre: x ∈ [−w/2, w/2], y ∈ [0, h],
    /// z ∈ [−d/2, d/2] for `size = [w, h, d]`.
    Box {
        /// Extents along the local x, y, z, all > 0.
        size: DVec3,
    },
    /// Points (a mesh's vertex positions, or its bounding corners) in the frame the pose
    /// maps from, for exact world bounds.
    Points {
        /// The points; never empty.
        points: Vec<DVec3>,
    },
}

/// Where an object's pivot is: the point that transformations turn and scale about.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pivot {
    /// The pose's origin: the bottom centre of the box for scene-file objects.
    Origin,
    /// The bottom centre of the object's current world bounding box (glTF objects, whose
    /// node origins are arbitrary).
    BottomCenter,
}

/// One object of a scene.
#[derive(Clone, Debug)]
pub struct Object {
    /// Unique in the scene, compared case-insensitively.
    pub name: String,
    /// The local shape.
    pub shape: Shape,
    /// The pivot rule.
    pub pivot: Pivot,
    /// The object this one rests on (an index into the scene's objects), if any.
    pub support: Option<usize>,
    /// Whether `support` came from the source file's hierarchy rather than geometry.
    pub support_from_file: bool,
    /// Words a person may use for the object besides its name (grounding reads them).
    pub labels: Labels,
    /// The local direction the object faces (a unit vector; +Z, glTF's convention, unless
    /// its source says otherwise).
    pub front: DVec3,
    pose: Multivector,
}

/// What an object is called besides its name, from its source file: the words grounding
/// (`crate::ground`) matches an instruction against.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Labels {
    /// What kind of thing it is, in plain words: scene JSON's `category`, a ProcTHOR
    /// `objectType` (`FloorLamp` → `floor lamp`), a glTF mesh name.
    pub category: Option<String>,
    /// Other names for this very object (scene JSON's `aliases`).
    pub aliases: Vec<String>,
    /// Attribute words: colours and materials (`color`, `material` in scene JSON; glTF
    /// material names).
    pub attributes: Vec<String>,
}

impl Object {
    /// An object with the given shape and pose.
    ///
    /// # Errors
    /// If the pose's scale is not a finite number > 0.
    pub fn new(
        name: impl Into<String>,
        shape: Shape,
        pose: Similarity,
        pivot: Pivot,
    ) -> Result<Self, CgaError> {
        Ok(Self {
            name: name.into(),
            shape,
            pivot,
            support: None,
            support_from_file: false,
            labels: Labels::default(),
            front: DVec3::Z,
            pose: pose.to_versor()?,
        })
    }

    /// A box object placed at `position` (its bottom centre) with a rotation and scale.
    pub fn new_box(
        name: impl Into<String>,
        size: DVec3,
        position: DVec3,
        rotation: DQuat,
        scale: f64,
    ) -> Result<Self, CgaError> {
        let pose = Similarity {
            translation: position,
            rotation,
            scale,
        };
        Self::new(name, Shape::Box { size }, pose, Pivot::Origin)
    }

    /// The pose versor `V = T·R·D`.
    pub fn pose(&self) -> &Multivector {
        &self.pose
    }

    /// The pose as translation (the world position of the local origin), rotation and
    /// scale.
    pub fn similarity(&self) -> Similarity {
        Similarity::from_versor(&self.pose).expect("poses are always similarities")
    }

    /// The local points whose image bounds the object: the 8 box corners or the mesh
    /// points.
    pub fn local_points(&self) -> Vec<DVec3> {
        match &self.shape {
            Shape::Box { size } => {
                let half = DVec3::new(size.x * 0.5, 0.0, size.z * 0.5);
                Aabb::new(-half, DVec3::new(half.x, size.y, half.z))
                    .corners()
                    .to_vec()
            }
            Shape::Points { points } => points.clone(),
        }
    }

    /// The world axis-aligned bounding box: the box of the transformed local points.
    pub fn world_aabb(&self) -> Aabb {
        // `PointMap` turns the pose into an affine map once (30–60 ns, against 650 ns for a
        // full decomposition) and is exact at any distance from the origin; a conformal
        // sandwich `M up(x) M̃` is not, since up(x) carries ½|x|².
        let map = cga::PointMap::new(&self.pose).expect("poses are always similarities");
        let transform = |p: DVec3| {
            map.transform_point(p)
                .expect("similarities move every point")
        };
        match &self.shape {
            Shape::Box { .. } => Aabb::from_points(self.local_points().into_iter().map(transform)),
            Shape::Points { points } => Aabb::from_points(points.iter().map(|&p| transform(p))),
        }
        .expect("shapes have at least one point")
    }

    /// The world direction the object faces: its rotation applied to its local front.
    pub fn world_front(&self) -> DVec3 {
        (self.similarity().rotation * self.front).normalize_or(DVec3::Z)
    }

    /// The pivot in world coordinates.
    pub fn pivot_point(&self) -> DVec3 {
        match self.pivot {
            Pivot::Origin => self.similarity().translation,
            Pivot::BottomCenter => self.world_aabb().bottom_center(),
        }
    }

    /// Replaces the pose by `world · V`, renormalised so rounding cannot build up.
    fn transform_world(&mut self, world: &Multivector) {
        let pose = *world * self.pose;
        let similarity = Similarity::from_versor(&pose).expect("similarities compose");
        self.pose = similarity.to_versor().expect("scale stays > 0");
    }
}

/// The world motions an edit applied, per object, so that it can be undone exactly.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AppliedMotion {
    /// Object index and the world-frame versor `W` that was applied to it (`V' = W V`).
    pub moves: Vec<(usize, Multivector)>,
}

impl AppliedMotion {
    /// The indices of the objects moved, in order.
    pub fn objects(&self) -> impl Iterator<Item = usize> + '_ {
        self.moves.iter().map(|(i, _)| *i)
    }
}

impl Scene {
    /// An empty scene.
    pub fn new(name: impl Into<String>) -> Self {
        Self {
            name: name.into(),
            bounds: None,
            objects: Vec::new(),
        }
    }

    /// The index of the object with this name (case-insensitive).
    pub fn find(&self, name: &str) -> Option<usize> {
        let name = name.trim().to_lowercase();
        self.objects
            .iter()
            .position(|o| o.name.to_lowercase() == name)
    }

    /// The index of the object with this name, or an error that suggests the closest
    /// names: `unknown object 'sofaa' — did you mean 'sofa'?`.
    pub fn resolve(&self, name: &str) -> Result<usize, String> {
        if let Some(i) = self.find(name) {
            return Ok(i);
        }
        let wanted = name.trim().to_lowercase();
        let mut scored: Vec<(f64, &str)> = self
            .objects
            .iter()
            .map(|o| {
                (
                    strsim::jaro_winkler(&wanted, &o.name.to_lowercase()),
                    o.name.as_str(),
                )
            })
            .filter(|(score, _)| *score >= 0.75)
            .collect();
        scored.sort_by(|a, b| b.0.total_cmp(&a.0));
        let suggestion = match scored.as_slice() {
            [] => String::new(),
            [(_, one)] => format!(" — did you mean '{one}'?"),
            [(_, a), (_, b), ..] => format!(" — did you mean '{a}' or '{b}'?"),
        };
        Err(format!("unknown object '{}'{suggestion}", name.trim()))
    }

    /// The world bounding box of every object, in order.
    pub fn world_aabbs(&self) -> Vec<Aabb> {
        self.objects.iter().map(Object::world_aabb).collect()
    }

    /// The floor height: the room's `min.y`, or 0.
    pub fn floor(&self) -> f64 {
        self.bounds.map_or(0.0, |b| b.min.y)
    }

    /// The objects resting on `index`, directly or through others (not `index` itself),
    /// in breadth-first order.
    pub fn carried_by(&self, index: usize) -> Vec<usize> {
        let mut out = Vec::new();
        let mut frontier = vec![index];
        while let Some(parent) = frontier.pop() {
            for (i, o) in self.objects.iter().enumerate() {
                if o.support == Some(parent) && i != index && !out.contains(&i) {
                    out.push(i);
                    frontier.push(i);
                }
            }
        }
        out
    }

    /// The world versor `W = T(p)·M·T(p)⁻¹` that applies `m` about the pivot `p` of
    /// object `index`.
    pub fn world_motion(&self, index: usize, m: &Multivector) -> Multivector {
        let p = self.objects[index].pivot_point();
        Multivector::translator(p) * *m * Multivector::translator(-p)
    }

    /// Applies the transformation `m` to object `index` about its pivot (SPEC §3) and,
    /// with `carry`, the same world motion to every object resting on it.
    pub fn apply(&mut self, index: usize, m: &Multivector, carry: bool) -> AppliedMotion {
        let world = self.world_motion(index, m);
        let mut targets = vec![index];
        if carry {
            targets.extend(self.carried_by(index));
        }
        self.apply_world(&targets, &world)
    }

    /// Applies the world versor `w` to the given objects: `V' = W V`.
    pub fn apply_world(&mut self, indices: &[usize], w: &Multivector) -> AppliedMotion {
        let mut motion = AppliedMotion::default();
        for &i in indices {
            self.objects[i].transform_world(w);
            motion.moves.push((i, *w));
        }
        motion
    }

    /// Undoes an applied motion exactly: each recorded `W` is reverted with `W⁻¹`, last
    /// first.
    pub fn undo(&mut self, motion: &AppliedMotion) {
        for (i, w) in motion.moves.iter().rev() {
            let inverse = w.inverse().expect("world motions are invertible");
            self.objects[*i].transform_world(&inverse);
        }
    }

    /// Finds which objects rest on which from geometry (see [`SUPPORT_GAP`]), keeping
    /// supports that came from the source file.
    pub fn detect_supports(&mut self) {
        support::detect(self);
    }
}

#[cfg(test)]
impl Scene {
    /// Test fixture: adds an unturned, unscaled box standing on `at` and returns its index.
    pub(crate) fn push_box(&mut self, name: &str, size: [f64; 3], at: [f64; 3]) -> usize {
        let object = Object::new_box(
            name,
            DVec3::from(size),
            DVec3::from(at),
            DQuat::IDENTITY,
            1.0,
        )
        .expect("a finite box");
        self.objects.push(object);
        self.objects.len() - 1
    }
}

#[cfg(test)]
mod tests;
