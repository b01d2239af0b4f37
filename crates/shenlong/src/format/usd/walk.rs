//! The walk of a stage's prims, parents first, into the tree the shared reading step needs
//! ([`super::super::facts`]) and what writing needs of each prim — over any [`Source`]: the
//! composed stage of the `openusd` crate, or a layer Shenlong read itself
//! ([`super::layer`]).

use super::super::facts::{Node, Tree};
use super::super::FormatError;
use super::xform::{self, Attr};
use super::PrimInfo;
use glam::DMat4;

/// What the walk reads of a stage's prims.
pub(super) trait Source {
    /// A prim, as this source names it.
    type Prim;
    /// Its children, in order.
    ///
    /// # Errors
    /// Composition failed below it.
    fn children(&self, prim: &Self::Prim) -> Result<Vec<Self::Prim>, FormatError>;
    /// Its path (`/World/Chair`).
    fn path(&self, prim: &Self::Prim) -> String;
    /// Its type (`Xform`, `Mesh`; empty when untyped).
    fn type_name(&self, prim: &Self::Prim) -> String;
    /// Whether it is active.
    fn active(&self, prim: &Self::Prim) -> bool;
    /// Whether it is a model of kind `component`.
    fn component(&self, prim: &Self::Prim) -> bool;
    /// An attribute's default value.
    fn attr(&self, prim: &Self::Prim, name: &str) -> Option<Attr>;
}

/// A prim to visit and its parent's place in the tree.
pub(super) struct Visit<P> {
    pub prim: P,
    /// Its parent's local-to-world transform (stage units).
    pub parent_world: DMat4,
    /// Its parent's index in the tree.
    pub parent: Option<usize>,
}

/// How the walk reads a stage.
pub(super) struct Walk {
    /// Stage units to Shenlong's frame.
    pub to_shenlong: DMat4,
    /// Whether the stage uses model kinds (its objects are its components).
    pub uses_kinds: bool,
    /// The most prims visited.
    pub max_prims: usize,
    /// How many prims the walk will likely visit (room is made for them at once), or 0.
    pub expected: usize,
}

impl Walk {
    /// Walks from `starts`, parents before children, on an explicit stack: no recursion
    /// however deep. Inactive prims and their subtrees are left out.
    ///
    /// # Errors
    /// More than `max_prims` prims, an op that is not finite, or composition failing.
    pub(super) fn run<S: Source>(
        &self,
        source: &S,
        starts: Vec<Visit<S::Prim>>,
    ) -> Result<(Tree, Vec<PrimInfo>), FormatError> {
        let expected = self.expected.min(self.max_prims);
        let mut tree = Tree::default();
        tree.nodes.reserve_exact(expected);
        let mut prims: Vec<PrimInfo> = Vec::with_capacity(expected);
        let mut stack = starts;
        stack.reverse();
        while let Some(Visit {
            prim,
            parent_world,
            parent,
        }) = stack.pop()
        {
            if !source.active(&prim) {
                continue;
            }
            if tree.nodes.len() >= self.max_prims {
                return Err(FormatError::too_large(format!(
                    "more than {} prims",
                    self.max_prims
                )));
            }
            let path = source.path(&prim);
            let attrs = |name: &str| source.attr(&prim, name);
            let (local, resets) = xform::local_transform(&attrs, &path)?;
            let parent_world = if resets {
                DMat4::IDENTITY
            } else {
                parent_world
            };
            let world = parent_world * local;
            let type_name = source.type_name(&prim);
            let shenlong = self.to_shenlong * world;
            let points = if matches!(type_name.as_str(), "Xform" | "Scope" | "") {
                Vec::new()
            } else {
                xform::geometry_points(&attrs, &type_name)
                    .into_iter()
                    .map(|p| shenlong.transform_point3(p))
                    .collect()
            };
            let text = |name: &str| {
                attrs(name)
                    .and_then(|a| a.text().map(str::to_string))
                    .filter(|t| !t.trim().is_empty())
            };
            let index = tree.nodes.len();
            tree.nodes.push(Node {
                name: path.rsplit('/').next().unwrap_or_default().to_string(),
                parent,
                world: shenlong,
                triangles: xform::geometry_triangles(&attrs, &type_name, points.len()),
                points,
                transformable: is_transformable(&type_name),
                model: self.uses_kinds && source.component(&prim),
                given_name: text("shenlong:name"),
                labels: crate::scene::Labels {
                    category: text("shenlong:category"),
                    ..crate::scene::Labels::default()
                },
                front: attrs("shenlong:front").and_then(|a| a.direction()),
                fallback: path.clone(),
            });
            prims.push(PrimInfo {
                resets,
                path,
                world,
                parent_world,
            });
            for child in source.children(&prim)?.into_iter().rev() {
                stack.push(Visit {
                    prim: child,
                    parent_world: world,
                    parent: Some(index),
                });
            }
        }
        Ok((tree, prims))
    }
}

/// Whether a prim of this type can carry a transform (an object's root).
fn is_transformable(type_name: &str) -> bool {
    !matches!(
        type_name,
        "" | "Scope"
            | "Material"
            | "Shader"
            | "NodeGraph"
            | "GeomSubset"
            | "Camera"
            | "DistantLight"
            | "DomeLight"
            | "RectLight"
            | "SphereLight"
            | "DiskLight"
            | "CylinderLight"
            | "RenderSettings"
            | "RenderProduct"
            | "RenderVar"
    )
}

/// The layer reader's prims as a source: indices into the layer.
impl Source for super::layer::Layer {
    type Prim = usize;

    fn children(&self, prim: &usize) -> Result<Vec<usize>, FormatError> {
        Ok(self.prims[*prim].children.clone())
    }
    fn path(&self, prim: &usize) -> String {
        self.prims[*prim].path.clone()
    }
    fn type_name(&self, prim: &usize) -> String {
        self.prims[*prim].type_name.clone()
    }
    fn active(&self, prim: &usize) -> bool {
        self.prims[*prim].active
    }
    fn component(&self, prim: &usize) -> bool {
        self.prims[*prim].kind.as_deref() == Some("component")
    }
    fn attr(&self, prim: &usize, name: &str) -> Option<Attr> {
        self.prims[*prim]
            .attrs
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, a)| a.clone())
    }
}
