//! The plain data a stage's walk gives ([`Walked`]), as bytes: what the reading child
//! process ([`super::sandbox`]) sends its parent. Decoding checks every length against
//! what is left, so no answer makes the parent allocate or index beyond it.

use super::super::facts::{Node, Tree};
use super::super::FormatError;
use super::{PrimInfo, StageFrame, UpAxis};
use crate::scene::Labels;
use glam::{DMat4, DVec3};

/// A stage walked: its prims as a tree, what writing needs of each, its frame as
/// authored and its default prim.
#[derive(Debug)]
pub(super) struct Walked {
    pub tree: Tree,
    pub prims: Vec<PrimInfo>,
    pub frame: StageFrame,
    pub default_prim: Option<String>,
}

#[derive(Default)]
struct Out(Vec<u8>);

impl Out {
    fn u64(&mut self, v: u64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    fn f64(&mut self, v: f64) {
        self.0.extend_from_slice(&v.to_le_bytes());
    }
    fn flag(&mut self, v: bool) {
        self.0.push(u8::from(v));
    }
    fn text(&mut self, s: &str) {
        self.u64(s.len() as u64);
        self.0.extend_from_slice(s.as_bytes());
    }
    fn opt_text(&mut self, s: Option<&str>) {
        self.flag(s.is_some());
        if let Some(s) = s {
            self.text(s);
        }
    }
    fn vec3(&mut self, v: DVec3) {
        for x in v.to_array() {
            self.f64(x);
        }
    }
    fn mat(&mut self, m: &DMat4) {
        for x in m.to_cols_array() {
            self.f64(x);
        }
    }
}

struct In<'a>(&'a [u8]);

fn malformed() -> FormatError {
    FormatError::invalid("the USD reader's answer is malformed")
}

impl In<'_> {
    fn take(&mut self, n: usize) -> Result<&[u8], FormatError> {
        if n > self.0.len() {
            return Err(malformed());
        }
        let (a, b) = self.0.split_at(n);
        self.0 = b;
        Ok(a)
    }
    fn u64(&mut self) -> Result<u64, FormatError> {
        Ok(u64::from_le_bytes(
            self.take(8)?.try_into().map_err(|_| malformed())?,
        ))
    }
    /// A count of items of at least `size` bytes each, checked against what is left.
    fn count(&mut self, size: usize) -> Result<usize, FormatError> {
        let n = usize::try_from(self.u64()?).map_err(|_| malformed())?;
        if n.checked_mul(size.max(1)).is_none_or(|b| b > self.0.len()) {
            return Err(malformed());
        }
        Ok(n)
    }
    fn f64(&mut self) -> Result<f64, FormatError> {
        Ok(f64::from_bits(self.u64()?))
    }
    fn flag(&mut self) -> Result<bool, FormatError> {
        Ok(self.take(1)?[0] != 0)
    }
    fn text(&mut self) -> Result<String, FormatError> {
        let n = self.count(1)?;
        String::from_utf8(self.take(n)?.to_vec()).map_err(|_| malformed())
    }
    fn opt_text(&mut self) -> Result<Option<String>, FormatError> {
        Ok(if self.flag()? {
            Some(self.text()?)
        } else {
            None
        })
    }
    fn vec3(&mut self) -> Result<DVec3, FormatError> {
        Ok(DVec3::new(self.f64()?, self.f64()?, self.f64()?))
    }
    fn mat(&mut self) -> Result<DMat4, FormatError> {
        let mut a = [0.0; 16];
        for x in &mut a {
            *x = self.f64()?;
        }
        Ok(DMat4::from_cols_array(&a))
    }
}

impl Walked {
    /// The walk as bytes.
    pub(super) fn encode(&self) -> Vec<u8> {
        let mut o = Out::default();
        o.flag(self.frame.up == UpAxis::Z);
        o.f64(self.frame.meters_per_unit);
        o.opt_text(self.default_prim.as_deref());
        o.u64(self.tree.nodes.len() as u64);
        for (node, prim) in self.tree.nodes.iter().zip(&self.prims) {
            o.text(&node.name);
            o.u64(node.parent.map_or(u64::MAX, |p| p as u64));
            o.mat(&node.world);
            o.u64(node.points.len() as u64);
            for p in &node.points {
                o.vec3(*p);
            }
            o.u64(node.triangles.len() as u64);
            for t in &node.triangles {
                for k in t {
                    o.u64(u64::from(*k));
                }
            }
            o.flag(node.transformable);
            o.flag(node.model);
            o.opt_text(node.given_name.as_deref());
            o.opt_text(node.labels.category.as_deref());
            o.flag(node.front.is_some());
            if let Some(f) = node.front {
                o.vec3(f);
            }
            o.text(&node.fallback);
            o.text(&prim.path);
            o.flag(prim.resets);
            o.mat(&prim.world);
            o.mat(&prim.parent_world);
        }
        o.0
    }

    /// The walk from bytes, every length checked.
    ///
    /// # Errors
    /// Bytes that are no walk.
    pub(super) fn decode(bytes: &[u8]) -> Result<Self, FormatError> {
        let mut i = In(bytes);
        let up = if i.flag()? { UpAxis::Z } else { UpAxis::Y };
        let meters_per_unit = i.f64()?;
        let default_prim = i.opt_text()?;
        // Each node takes well over 64 bytes.
        let n = i.count(64)?;
        let mut tree = Tree::default();
        let mut prims = Vec::with_capacity(n);
        tree.nodes.reserve(n);
        for k in 0..n {
            let name = i.text()?;
            let parent = match i.u64()? {
                u64::MAX => None,
                p => Some(
                    usize::try_from(p)
                        .ok()
                        .filter(|&p| p < k)
                        .ok_or_else(malformed)?,
                ),
            };
            let world = i.mat()?;
            let count = i.count(24)?;
            let mut points = Vec::with_capacity(count);
            for _ in 0..count {
                points.push(i.vec3()?);
            }
            let count = i.count(24)?;
            let mut triangles = Vec::with_capacity(count);
            for _ in 0..count {
                let mut t = [0u32; 3];
                for k in &mut t {
                    *k = u32::try_from(i.u64()?)
                        .ok()
                        .filter(|&k| (k as usize) < points.len())
                        .ok_or_else(malformed)?;
                }
                triangles.push(t);
            }
            let transformable = i.flag()?;
            let model = i.flag()?;
            let given_name = i.opt_text()?;
            let category = i.opt_text()?;
            let front = if i.flag()? { Some(i.vec3()?) } else { None };
            let fallback = i.text()?;
            tree.nodes.push(Node {
                name,
                parent,
                world,
                points,
                triangles,
                transformable,
                model,
                given_name,
                labels: Labels {
                    category,
                    ..Labels::default()
                },
                front,
                fallback,
            });
            prims.push(PrimInfo {
                path: i.text()?,
                resets: i.flag()?,
                world: i.mat()?,
                parent_world: i.mat()?,
            });
        }
        if !i.0.is_empty() {
            return Err(malformed());
        }
        Ok(Walked {
            tree,
            prims,
            frame: StageFrame {
                up,
                meters_per_unit,
            },
            default_prim,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_walk_round_trips_and_cut_answers_are_refused() {
        let mut tree = Tree::default();
        tree.nodes.push(Node {
            name: "Chair".into(),
            points: vec![DVec3::new(1.0, 2.0, 3.0); 3],
            triangles: vec![[0, 1, 2]],
            transformable: true,
            given_name: Some("chair".into()),
            front: Some(DVec3::X),
            fallback: "/World/Chair".into(),
            ..Node::default()
        });
        let walked = Walked {
            tree,
            prims: vec![PrimInfo {
                path: "/World/Chair".into(),
                resets: false,
                world: DMat4::from_translation(DVec3::X),
                parent_world: DMat4::IDENTITY,
            }],
            frame: StageFrame {
                up: UpAxis::Z,
                meters_per_unit: 0.01,
            },
            default_prim: Some("World".into()),
        };
        let bytes = walked.encode();
        let back = Walked::decode(&bytes).unwrap();
        assert_eq!(back.tree.nodes[0].points, walked.tree.nodes[0].points);
        assert_eq!(back.tree.nodes[0].triangles, [[0, 1, 2]]);
        assert_eq!(back.prims[0].path, "/World/Chair");
        assert_eq!(back.frame.up, UpAxis::Z);
        for cut in 0..bytes.len() {
            assert!(Walked::decode(&bytes[..cut]).is_err(), "cut at {cut}");
        }
        // A count of 2^60 nodes is refused before anything is allocated for them.
        let mut huge = bytes[..bytes.len()].to_vec();
        let at = 1 + 8 + 1 + 8 + 5;
        huge[at..at + 8].copy_from_slice(&(1u64 << 60).to_le_bytes());
        assert!(Walked::decode(&huge).is_err());
    }
}
