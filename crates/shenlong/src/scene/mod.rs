//! The scene model: named objects with a shape and a pose.
//!
//! An object's pose is the similarity `V = T·R·D` that maps its local shape into the world
//! (SPEC §2–§3), kept as its parts — translation, unit quaternion, scale — so that it stays
//! exact however many edits it takes. A transformation `M` from an instruction is a CGA
//! versor; it is decomposed once (refused if it is not `T·R·D`), made to act in the frame
//! centred at the object's pivot with the world's axes, `W = T(p)·M·T(p)⁻¹`, and composed
//! with the pose on its parts: `V' = W·V`. Objects resting on the moved one are carried
//! along with the same world motion. Every applied motion records the poses it replaced,
//! so undoing it is exact to the bit.

pub mod form;
pub mod listing;
pub mod mesh;
mod support;

use crate::geometry::Aabb;
use cga::{CgaError, Multivector, Similarity};
use glam::{DQuat, DVec3};

pub use form::{Form, Room, Seat};
pub use support::{FLOOR_LEVEL, SUPPORT_GAP};

/// The largest coordinate (and box extent) Shenlong keeps exact, in metres: positions and
/// sizes beyond it are refused on reading, and an edit that would go beyond it is refused.
pub const MAX_COORDINATE: f64 = 1e6;
/// The smallest uniform scale accepted.
pub const MIN_SCALE: f64 = 1e-6;
/// The largest uniform scale accepted.
pub const MAX_SCALE: f64 = 1e6;

/// Why a transformation cannot be applied to an object: nothing moved.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum MotionError {
    /// The versor is not a product of a translation, a rotation and a uniform scale.
    #[error("the transformation is not a translation, rotation and uniform scale: {0}")]
    NotSimilarity(#[source] CgaError),
    /// The transformation's own translation is beyond the exact range.
    #[error("the move of {distance:.3e} m is beyond the {max:.0e} m Shenlong keeps exact", max = MAX_COORDINATE)]
    TooFar {
        /// How far the transformation moves the origin, in metres.
        distance: f64,
    },
    /// The transformation's own scale is outside the accepted range.
    #[error("the scale {0:.3e} is outside [{min:.0e}, {max:.0e}]", min = MIN_SCALE, max = MAX_SCALE)]
    Scale(f64),
    /// The motion would take an object's pose beyond the limits.
    #[error("the edit would take '{0}' beyond the limits Shenlong keeps exact (|position| ≤ {max:.0e} m, scale in [{min:.0e}, {smax:.0e}])", max = MAX_COORDINATE, min = MIN_SCALE, smax = MAX_SCALE)]
    LeavesLimits(String),
}

/// Whether a pose is within the limits Shenlong keeps exact: a finite position within
/// [`MAX_COORDINATE`] of the origin on every axis and a scale in
/// [[`MIN_SCALE`], [`MAX_SCALE`]].
#[must_use]
pub fn pose_within_limits(pose: &Similarity) -> bool {
    pose.is_valid()
        && pose.translation.abs().max_element() <= MAX_COORDINATE
        && (MIN_SCALE..=MAX_SCALE).contains(&pose.scale)
}

/// No object has the name asked for; the closest names, if any are close.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("unknown object '{name}'{}", did_you_mean(suggestions))]
pub struct UnknownObject {
    /// The name asked for.
    pub name: String,
    /// Up to two names of the scene that are close to it, closest first.
    pub suggestions: Vec<String>,
}

fn did_you_mean(suggestions: &[String]) -> String {
    match suggestions {
        [] => String::new(),
        [one] => format!(" — did you mean '{one}'?"),
        [a, b, ..] => format!(" — did you mean '{a}' or '{b}'?"),
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
    /// What of its box is solid, as its source file says (scene JSON's `form`); `None`:
    /// read from its kind (`ground::kind::form_of`).
    pub form: Option<Form>,
    /// What its mesh shows of the room under it or in it, as read when its file was
    /// (`mesh::measure`); `None`: it has no mesh, or one that shows nothing a box does not.
    pub measured: Option<mesh::Measured>,
    pose: Similarity,
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
    /// An object with the given shape and pose (its rotation is normalised).
    ///
    /// # Errors
    /// If the pose's scale is not a finite number > 0, or a component is not finite.
    pub fn new(
        name: impl Into<String>,
        shape: Shape,
        pose: Similarity,
        pivot: Pivot,
    ) -> Result<Self, CgaError> {
        if !(pose.scale.is_finite() && pose.scale > 0.0) {
            return Err(CgaError::BadScale(pose.scale));
        }
        let rotation = pose.rotation.normalize();
        if !(pose.translation.is_finite() && rotation.is_finite()) {
            return Err(CgaError::NotFinite(format!("{pose:?}")));
        }
        let rotation = if rotation.w < 0.0 {
            -rotation
        } else {
            rotation
        };
        Ok(Self {
            name: name.into(),
            shape,
            pivot,
            support: None,
            support_from_file: false,
            labels: Labels::default(),
            front: DVec3::Z,
            form: None,
            measured: None,
            pose: Similarity { rotation, ..pose },
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

    /// The pose: translation (the world position of the local origin), rotation and
    /// scale.
    #[must_use]
    pub fn similarity(&self) -> Similarity {
        self.pose
    }

    /// This object as it was before an edit: the pose it had and the support it rested
    /// on (`(support, from the file)`); everything else an edit does not change.
    #[must_use]
    pub(crate) fn as_it_was(&self, pose: Similarity, support: (Option<usize>, bool)) -> Object {
        Object {
            pose,
            support: support.0,
            support_from_file: support.1,
            ..self.clone()
        }
    }

    /// Whether this object's pose differs from `other`'s beyond rounding: what counts as
    /// a move for the edit history and for the editor's `moved` list.
    #[must_use]
    pub fn pose_differs(&self, other: &Object) -> bool {
        let (p, q) = (self.pose, other.pose);
        (p.translation - q.translation).length() > 1e-12
            || p.rotation.dot(q.rotation).abs() < 1.0 - 1e-15
            || (p.scale - q.scale).abs() > 1e-12
    }

    /// The local points whose image bounds the object: the 8 box corners or the mesh
    /// points.
    pub fn local_points(&self) -> Vec<DVec3> {
        match &self.shape {
            Shape::Box { size } => box_corners(*size).to_vec(),
            Shape::Points { points } => points.clone(),
        }
    }

    /// The world axis-aligned bounding box: the box of the transformed local points.
    #[must_use]
    pub fn world_aabb(&self) -> Aabb {
        // The pose as a matrix once: 9 multiply-adds per point, exact at any distance from
        // the origin (a conformal sandwich `M up(x) M̃` is not, since up(x) carries ½|x|²).
        let linear = glam::DMat3::from_quat(self.pose.rotation) * self.pose.scale;
        let t = self.pose.translation;
        let transform = |p: DVec3| linear * p + t;
        let bounds = match &self.shape {
            Shape::Box { size } => Aabb::from_points(box_corners(*size).into_iter().map(transform)),
            Shape::Points { points } => Aabb::from_points(points.iter().map(|&p| transform(p))),
        };
        // `Points` is never empty (the readers refuse empty meshes); the pose's origin
        // stands in for a shape built empty by hand.
        bounds.unwrap_or_else(|| Aabb::new(t, t))
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

    /// Replaces the pose by `world · V` and returns the pose it replaced.
    fn transform_world(&mut self, world: &Similarity) -> Similarity {
        let before = self.pose;
        self.pose = world.compose(&before);
        before
    }
}

/// The 8 corners of a box shape of this size, pivot at its bottom centre.
fn box_corners(size: DVec3) -> [DVec3; 8] {
    let half = DVec3::new(size.x * 0.5, 0.0, size.z * 0.5);
    Aabb::new(-half, DVec3::new(half.x, size.y, half.z)).corners()
}

/// One object's share of an applied motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Move {
    /// The object's index.
    pub object: usize,
    /// The world-frame motion `W` applied to it (`V' = W·V`).
    pub world: Similarity,
    /// Its pose before, which undo restores exactly.
    pub before: Similarity,
}

/// The world motions an edit applied, per object, so that it can be undone exactly.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct AppliedMotion {
    /// What was applied to each object, in order.
    pub moves: Vec<Move>,
}

impl AppliedMotion {
    /// The indices of the objects moved, in order.
    pub fn objects(&self) -> impl Iterator<Item = usize> + '_ {
        self.moves.iter().map(|m| m.object)
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
    ///
    /// # Errors
    /// No object has the name.
    pub fn resolve(&self, name: &str) -> Result<usize, UnknownObject> {
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
        Err(UnknownObject {
            name: name.trim().to_string(),
            suggestions: scored
                .iter()
                .take(2)
                .map(|(_, n)| (*n).to_string())
                .collect(),
        })
    }

    /// The world bounding box of every object, in order.
    pub fn world_aabbs(&self) -> Vec<Aabb> {
        self.objects.iter().map(Object::world_aabb).collect()
    }

    /// The floor height: the room's `min.y`, or 0.
    pub fn floor(&self) -> f64 {
        self.bounds.map_or(0.0, |b| b.min.y)
    }

    /// Whether object `i` hangs: it rests on nothing, above the floor (a picture, a
    /// whiteboard, a wall shelf — or something left in the air).
    #[must_use]
    pub fn hangs(&self, i: usize) -> bool {
        self.hangs_at(i, &self.objects[i].world_aabb())
    }

    /// [`Scene::hangs`] with object `i`'s world box already known.
    #[must_use]
    pub fn hangs_at(&self, i: usize, world: &Aabb) -> bool {
        self.objects[i].support.is_none() && world.min.y > self.floor() + SUPPORT_GAP
    }

    /// Per object, the objects resting directly on it (none on itself), in one pass.
    #[must_use]
    pub fn resting_on_each(&self) -> Vec<Vec<usize>> {
        let mut on: Vec<Vec<usize>> = vec![Vec::new(); self.objects.len()];
        for (i, o) in self.objects.iter().enumerate() {
            if let Some(s) = o.support.filter(|&s| s < on.len() && s != i) {
                on[s].push(i);
            }
        }
        on
    }

    /// Whether object `i` rests on `under`, directly or through what it stands on.
    #[must_use]
    pub fn rests_on_through(&self, i: usize, under: usize) -> bool {
        let mut at = i;
        // A support chain is at most as long as the scene (a cycle ends the walk).
        for _ in 0..self.objects.len() {
            match self.objects.get(at).and_then(|o| o.support) {
                Some(s) if s == under => return true,
                Some(s) if s != at => at = s,
                _ => return false,
            }
        }
        false
    }

    /// The objects resting on `index`, directly or through others (not `index` itself),
    /// in breadth-first order.
    pub fn carried_by(&self, index: usize) -> Vec<usize> {
        self.carried_by_except(index, &[])
    }

    /// [`Scene::carried_by`] that stops at the `held` objects: they, and what rests only
    /// on them, stay.
    #[must_use]
    pub fn carried_by_except(&self, index: usize, held: &[usize]) -> Vec<usize> {
        // Most objects carry nothing: found in one pass without allocating, so that a
        // group edit of thousands of objects costs each of them one pass, not an index.
        if !self.objects.iter().any(|o| o.support == Some(index)) {
            return Vec::new();
        }
        // What rests on each object, indexed once: a chain of thousands costs its length.
        let on = self.resting_on_each();
        let mut seen = vec![false; self.objects.len()];
        for &h in held.iter().chain(std::iter::once(&index)) {
            if let Some(s) = seen.get_mut(h) {
                *s = true;
            }
        }
        let mut out = Vec::new();
        let mut frontier = vec![index];
        while let Some(parent) = frontier.pop() {
            for &i in on.get(parent).map_or(&[][..], Vec::as_slice) {
                if !seen[i] {
                    seen[i] = true;
                    out.push(i);
                    frontier.push(i);
                }
            }
        }
        out
    }

    /// The world motion `W = T(p)·M·T(p)⁻¹` that applies the transformation `m` about the
    /// pivot `p` of object `index`.
    ///
    /// # Errors
    /// If `m` is not a translation, rotation and uniform scale, moves the origin beyond
    /// twice [`MAX_COORDINATE`] or scales outside [[`MIN_SCALE`], [`MAX_SCALE`]].
    pub fn world_motion(&self, index: usize, m: &Multivector) -> Result<Similarity, MotionError> {
        let step = Similarity::from_versor(m).map_err(MotionError::NotSimilarity)?;
        self.world_motion_of(index, &step)
    }

    /// [`Scene::world_motion`] of a transformation already split into T·R·D.
    ///
    /// # Errors
    /// As [`Scene::world_motion`], but for the split.
    pub fn world_motion_of(
        &self,
        index: usize,
        step: &Similarity,
    ) -> Result<Similarity, MotionError> {
        if !step.translation.is_finite()
            || step.translation.abs().max_element() > 2.0 * MAX_COORDINATE
        {
            return Err(MotionError::TooFar {
                distance: step.translation.length(),
            });
        }
        if !(step.scale.is_finite() && (MIN_SCALE..=MAX_SCALE).contains(&step.scale)) {
            return Err(MotionError::Scale(step.scale));
        }
        Ok(step.about(self.objects[index].pivot_point()))
    }

    /// Applies the transformation `m` to object `index` about its pivot (SPEC §3) and,
    /// with `carry`, the same world motion to every object resting on it.
    ///
    /// # Errors
    /// See [`Scene::world_motion`]; also if the motion would leave any pose it moves
    /// beyond the limits ([`pose_within_limits`]). Nothing moves then.
    pub fn apply(
        &mut self,
        index: usize,
        m: &Multivector,
        carry: bool,
    ) -> Result<AppliedMotion, MotionError> {
        self.apply_holding(index, m, carry, &[])
    }

    /// [`Scene::apply`] that carries none of `held` (objects that must stay where they
    /// are) and nothing that rests on them.
    ///
    /// # Errors
    /// As [`Scene::apply`].
    pub fn apply_holding(
        &mut self,
        index: usize,
        m: &Multivector,
        carry: bool,
        held: &[usize],
    ) -> Result<AppliedMotion, MotionError> {
        let step = Similarity::from_versor(m).map_err(MotionError::NotSimilarity)?;
        self.move_holding(index, &step, carry, held)
    }

    /// [`Scene::apply_holding`] of a transformation already split into T·R·D (as an
    /// answer's [`crate::expr::Transformation`] carries it): the split is not made again.
    ///
    /// # Errors
    /// As [`Scene::apply`].
    pub fn move_holding(
        &mut self,
        index: usize,
        step: &Similarity,
        carry: bool,
        held: &[usize],
    ) -> Result<AppliedMotion, MotionError> {
        let world = self.world_motion_of(index, step)?;
        let mut targets = vec![index];
        if carry {
            targets.extend(self.carried_by_except(index, held));
        }
        for &i in &targets {
            let o = &self.objects[i];
            if !pose_within_limits(&world.compose(&o.pose)) {
                return Err(MotionError::LeavesLimits(o.name.clone()));
            }
        }
        Ok(self.apply_world(&targets, &world))
    }

    /// Applies the world motion `w` to the given objects: `V' = W·V`.
    pub fn apply_world(&mut self, indices: &[usize], w: &Similarity) -> AppliedMotion {
        let moves = indices
            .iter()
            .map(|&object| Move {
                object,
                world: *w,
                before: self.objects[object].transform_world(w),
            })
            .collect();
        AppliedMotion { moves }
    }

    /// Undoes an applied motion exactly: each object gets back the pose it had, last move
    /// first.
    pub fn undo(&mut self, motion: &AppliedMotion) {
        for m in motion.moves.iter().rev() {
            self.objects[m.object].pose = m.before;
        }
    }

    /// Finds which objects rest on which from geometry (see [`SUPPORT_GAP`]), keeping
    /// supports that came from the source file.
    pub fn detect_supports(&mut self) {
        support::detect(self);
    }

    /// [`Scene::detect_supports`] for only what moving `changed` can have changed, given
    /// the world boxes of every object (`boxes`, already updated) and a grid over them;
    /// the objects marked in `hung` (that hung when the edit began) do not come to rest on
    /// what moved under them (an empty slice marks none).
    pub fn detect_supports_around(
        &mut self,
        boxes: &[Aabb],
        grid: &crate::geometry::FloorGrid,
        changed: &[usize],
        hung: &[bool],
    ) {
        support::detect_around(self, boxes, grid, changed, hung);
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
