//! Pictures of scenes: a top-down plan, as SVG or PNG.
//!
//! The plan looks down the −Y axis: +X to the right, +Z (forward) toward the bottom of the
//! picture. Each object is drawn as its footprint — the outline of its shape seen from
//! above — with its name, and a tick toward its front (local +Z). Objects resting on others
//! are drawn in a warmer colour over their support. Given the scene before an edit, the
//! objects that moved are highlighted, and their old footprints are ghosted with arrows to
//! the new ones.

use crate::geometry::Aabb;
use crate::scene::{Object, Scene, Shape};
use glam::{DVec2, DVec3};
use std::fmt::Write;

/// Width of the picture, in pixels.
const WIDTH: f64 = 1000.0;
/// Margin around the drawing, in pixels.
const MARGIN: f64 = 40.0;
/// Height reserved for the title and legend, in pixels.
const HEADER: f64 = 36.0;
/// Longest label drawn, in characters; longer names are cut with "…".
const MAX_LABEL_CHARS: usize = 32;
/// Longest name kept in an object's hover title.
const MAX_TITLE_CHARS: usize = 200;
/// Objects narrower than this on the plan get no label: it could not be read.
const MIN_LABELLED_PX: f64 = 4.0;

/// `text` cut to `max` characters, with "…" when cut.
fn short(text: &str, max: usize) -> String {
    if text.chars().count() <= max {
        text.to_string()
    } else {
        let mut s: String = text.chars().take(max.saturating_sub(1)).collect();
        s.push('…');
        s
    }
}

/// The footprint of an object: the convex outline of its shape projected on the floor,
/// as (x, z) points in counter-clockwise order.
pub fn footprint(object: &Object) -> Vec<DVec2> {
    let pose = object.similarity();
    let points: Vec<DVec2> = object
        .local_points()
        .into_iter()
        .map(|p| {
            let w = pose.transform_point(p);
            DVec2::new(w.x, w.z)
        })
        .collect();
    convex_hull(points)
}

/// Andrew's monotone chain; collinear points are dropped.
fn convex_hull(mut points: Vec<DVec2>) -> Vec<DVec2> {
    points.sort_by(|a, b| a.x.total_cmp(&b.x).then(a.y.total_cmp(&b.y)));
    points.dedup_by(|a, b| (*a - *b).length() < 1e-12);
    if points.len() < 3 {
        return points;
    }
    let cross = |o: DVec2, a: DVec2, b: DVec2| (a - o).perp_dot(b - o);
    let mut hull: Vec<DVec2> = Vec::with_capacity(points.len() * 2);
    for pass in 0..2 {
        let start = hull.len();
        let iter: Box<dyn Iterator<Item = &DVec2>> = if pass == 0 {
            Box::new(points.iter())
        } else {
            Box::new(points.iter().rev())
        };
        for &p in iter {
            while hull.len() >= start + 2
                && cross(hull[hull.len() - 2], hull[hull.len() - 1], p) <= 0.0
            {
                hull.pop();
            }
            hull.push(p);
        }
        hull.pop();
    }
    hull
}

/// Whether an object stands elsewhere in `after` than in `before`: by its pose (scene JSON),
/// or by where its points are in the world (a glTF or USD file read again after the edit,
/// whose objects' poses start at the identity each time they are read).
fn moved_between(before: &crate::scene::Object, after: &crate::scene::Object) -> bool {
    let (sa, sb) = (after.similarity(), before.similarity());
    let pose = (sa.translation - sb.translation).length() > 1e-9
        || sa.rotation.dot(sb.rotation).abs() < 1.0 - 1e-12
        || (sa.scale - sb.scale).abs() > 1e-12;
    let world = |o: &crate::scene::Object| -> Vec<glam::DVec3> {
        let s = o.similarity();
        o.local_points()
            .into_iter()
            .take(16)
            .map(|p| s.translation + s.rotation * (p * s.scale))
            .collect()
    };
    let (pa, pb) = (world(after), world(before));
    let size = 1.0 + after.world_aabb().size().length();
    pose || pa.len() != pb.len()
        || pa
            .iter()
            .zip(&pb)
            .any(|(x, y)| (*x - *y).length() > 1e-9 * size)
}

/// The plan of `scene` as an SVG document; with `before`, the edit from `before` to
/// `scene` is shown (the same objects, in the same order).
pub fn plan_svg(scene: &Scene, before: Option<&Scene>) -> String {
    let footprints: Vec<Vec<DVec2>> = scene.objects.iter().map(footprint).collect();
    let old: Option<Vec<Vec<DVec2>>> = before.map(|b| b.objects.iter().map(footprint).collect());
    let moved: Vec<bool> = match before {
        Some(b) => scene
            .objects
            .iter()
            .zip(&b.objects)
            .map(|(a, b)| moved_between(b, a))
            .collect(),
        None => vec![false; scene.objects.len()],
    };
    let plan = Plan::fit(scene.bounds, footprints.iter().chain(old.iter().flatten()));
    let mut svg = String::new();
    plan.header(&mut svg, scene);
    if let Some(old) = &old {
        plan.ghosts(&mut svg, old, &moved);
    }
    // Objects, lowest top first, so things resting on others are drawn over them.
    let boxes = scene.world_aabbs();
    let mut order: Vec<usize> = (0..scene.objects.len()).collect();
    order.sort_by(|&a, &b| boxes[a].max.y.total_cmp(&boxes[b].max.y));
    for &i in &order {
        plan.object(&mut svg, &scene.objects[i], &footprints[i], moved[i]);
    }
    if let Some(before) = before {
        plan.arrows(&mut svg, before, scene, &moved);
    }
    plan.labels(&mut svg, scene, &footprints, &order);
    svg.push_str("</svg>\n");
    svg
}

/// The drawing's frame: the part of the floor drawn, metres to pixels, the picture's
/// height.
struct Plan {
    extent: Aabb,
    /// Pixels per metre.
    k: f64,
    height: f64,
}

impl Plan {
    /// The frame that holds the room and every footprint given.
    fn fit<'a>(room: Option<Aabb>, footprints: impl Iterator<Item = &'a Vec<DVec2>>) -> Self {
        let mut extent: Option<Aabb> = room;
        for p in footprints.flatten() {
            let b = Aabb::new(DVec3::new(p.x, 0.0, p.y), DVec3::new(p.x, 0.0, p.y));
            extent = Some(extent.map_or(b, |e| e.union(&b)));
        }
        let extent = extent.unwrap_or(Aabb::new(DVec3::splat(-1.0), DVec3::splat(1.0)));
        let size = DVec2::new(extent.size().x.max(1e-6), extent.size().z.max(1e-6));
        let k = (WIDTH - 2.0 * MARGIN) / size.x;
        let height = (size.y * k + 2.0 * MARGIN + HEADER).min(4000.0);
        let k = k.min((height - 2.0 * MARGIN - HEADER) / size.y);
        Self { extent, k, height }
    }

    /// A floor point (x, z) in pixels.
    fn to_px(&self, p: DVec2) -> DVec2 {
        DVec2::new(
            MARGIN + (p.x - self.extent.min.x) * self.k,
            HEADER + MARGIN + (p.y - self.extent.min.z) * self.k,
        )
    }

    /// A closed SVG path through floor points.
    fn path(&self, points: &[DVec2]) -> String {
        let mut d = String::new();
        for (i, p) in points.iter().enumerate() {
            let q = self.to_px(*p);
            let _ = write!(
                d,
                "{}{:.1},{:.1} ",
                if i == 0 { "M" } else { "L" },
                q.x,
                q.y
            );
        }
        d.push('Z');
        d
    }

    /// The document's start, the title, the room and a scale bar.
    fn header(&self, svg: &mut String, scene: &Scene) {
        let height = self.height;
        let _ = writeln!(
            svg,
            r##"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH:.0}" height="{height:.0}" viewBox="0 0 {WIDTH:.0} {height:.0}" font-family="DejaVu Sans, Arial, sans-serif">"##
        );
        svg.push_str(
            r##"<defs><marker id="arrow" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#1b7f3b"/></marker></defs>
<rect width="100%" height="100%" fill="#ffffff"/>
"##,
        );
        let title = escape(&scene.name);
        let _ = writeln!(
            svg,
            r##"<text x="{MARGIN}" y="24" font-size="16" font-weight="bold" fill="#222">{title}</text><text x="{:.0}" y="24" font-size="12" fill="#555" text-anchor="end">top view · +x → right · +z (forward) ↓ down</text>"##,
            WIDTH - MARGIN
        );
        if let Some(room) = scene.bounds {
            let a = self.to_px(DVec2::new(room.min.x, room.min.z));
            let b = self.to_px(DVec2::new(room.max.x, room.max.z));
            let _ = writeln!(
                svg,
                r##"<rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="#f7f5f0" stroke="#444" stroke-width="4"/>"##,
                a.x,
                a.y,
                b.x - a.x,
                b.y - a.y
            );
        }
        // A 1 m scale bar (or the largest power of ten that fits).
        let k = self.k;
        let mut unit = 1.0;
        while unit * k > 200.0 {
            unit /= 10.0;
        }
        while unit * k < 20.0 {
            unit *= 10.0;
        }
        let bar_y = height - 14.0;
        let _ = writeln!(
            svg,
            r##"<line x1="{MARGIN}" y1="{bar_y:.1}" x2="{:.1}" y2="{bar_y:.1}" stroke="#222" stroke-width="3"/><text x="{:.1}" y="{:.1}" font-size="11" fill="#222">{unit} m</text>"##,
            MARGIN + unit * k,
            MARGIN + unit * k + 6.0,
            bar_y + 4.0
        );
    }

    /// The old footprints of the objects that moved, ghosted.
    fn ghosts(&self, svg: &mut String, old: &[Vec<DVec2>], moved: &[bool]) {
        for (i, points) in old.iter().enumerate() {
            if moved[i] {
                let _ = writeln!(
                    svg,
                    r##"<path d="{}" fill="none" stroke="#888" stroke-width="1.5" stroke-dasharray="5,4"/>"##,
                    self.path(points)
                );
            }
        }
    }

    /// One object's footprint (green when it moved, brown when it rests on another), and
    /// for a box a tick from its centre toward its front.
    fn object(&self, svg: &mut String, object: &Object, footprint: &[DVec2], moved: bool) {
        let (fill, stroke) = if moved {
            ("#9fe0a8", "#1b7f3b")
        } else if object.support.is_some() {
            ("#f6c79a", "#a0522d")
        } else {
            ("#cfdff2", "#3a5a80")
        };
        let _ = writeln!(
            svg,
            r##"<path d="{}" fill="{fill}" fill-opacity="0.85" stroke="{stroke}" stroke-width="1.2"><title>{}</title></path>"##,
            self.path(footprint),
            escape(&short(&object.name, MAX_TITLE_CHARS))
        );
        if let Shape::Box { size } = &object.shape {
            let pose = object.similarity();
            let centre = pose.transform_point(DVec3::new(0.0, 0.0, 0.0));
            let reach = (object.front * *size * 0.5).length();
            let front = pose.transform_point(object.front * reach);
            let (a, b) = (
                self.to_px(DVec2::new(centre.x, centre.z)),
                self.to_px(DVec2::new(front.x, front.z)),
            );
            if (b - a).length() > 3.0 {
                let _ = writeln!(
                    svg,
                    r##"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{stroke}" stroke-width="1"/>"##,
                    a.x, a.y, b.x, b.y
                );
            }
        }
    }

    /// Arrows from where the moved objects were to where they are.
    fn arrows(&self, svg: &mut String, before: &Scene, scene: &Scene, moved: &[bool]) {
        for (i, (a, b)) in before.objects.iter().zip(&scene.objects).enumerate() {
            if !moved[i] {
                continue;
            }
            let (p, q) = (a.world_aabb().center(), b.world_aabb().center());
            let (p, q) = (
                self.to_px(DVec2::new(p.x, p.z)),
                self.to_px(DVec2::new(q.x, q.z)),
            );
            if (q - p).length() > 4.0 {
                let _ = writeln!(
                    svg,
                    r##"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#1b7f3b" stroke-width="2" marker-end="url(#arrow)"/>"##,
                    p.x, p.y, q.x, q.y
                );
            }
        }
    }

    /// Labels last, on top of everything, with a white halo; each is nudged up or down
    /// until it clears the labels already placed (supports first, then what rests on
    /// them). A label that finds no clear place, or whose object is too small to read on
    /// the plan, is left out; names are cut to a readable length. Placed labels are kept
    /// in a grid, so this is linear in the objects.
    fn labels(&self, svg: &mut String, scene: &Scene, footprints: &[Vec<DVec2>], order: &[usize]) {
        const CELL: f64 = 64.0;
        let mut placed: Vec<(DVec2, DVec2)> = Vec::new();
        let mut grid: std::collections::HashMap<(i64, i64), Vec<usize>> =
            std::collections::HashMap::new();
        let cell = |p: DVec2| ((p.x / CELL).floor() as i64, (p.y / CELL).floor() as i64);
        for &i in order {
            let footprint_px: Vec<DVec2> = footprints[i].iter().map(|p| self.to_px(*p)).collect();
            let extent = footprint_px
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    (lo.min(p.x), hi.max(p.x))
                });
            if extent.1 - extent.0 < MIN_LABELLED_PX {
                continue;
            }
            let centre = footprints[i].iter().fold(DVec2::ZERO, |s, p| s + *p)
                / footprints[i].len().max(1) as f64;
            let c = self.to_px(centre);
            let name = short(&scene.objects[i].name, MAX_LABEL_CHARS);
            let half = DVec2::new(3.3 * name.chars().count() as f64 + 2.0, 7.0);
            let clear = |at: DVec2| {
                let (cx, cy) = cell(at);
                let reach = ((half.x + 3.3 * MAX_LABEL_CHARS as f64 + 2.0) / CELL).ceil() as i64;
                for gx in cx - reach..=cx + reach {
                    for gy in cy - 1..=cy + 1 {
                        for &k in grid.get(&(gx, gy)).into_iter().flatten() {
                            let (p, h) = placed[k];
                            if (at.x - p.x).abs() < half.x + h.x
                                && (at.y - p.y).abs() < half.y + h.y
                            {
                                return false;
                            }
                        }
                    }
                }
                true
            };
            let Some(at) = [0.0, 13.0, -13.0, 26.0, -26.0, 39.0, -39.0]
                .iter()
                .map(|dy| DVec2::new(c.x, c.y + dy))
                .find(|at| clear(*at))
            else {
                continue;
            };
            grid.entry(cell(at)).or_default().push(placed.len());
            placed.push((at, half));
            let label = escape(&name);
            let _ = writeln!(
                svg,
                r##"<text x="{:.1}" y="{:.1}" font-size="11" text-anchor="middle" dominant-baseline="middle" fill="#111" stroke="#fff" stroke-width="3" paint-order="stroke">{label}</text>"##,
                at.x, at.y
            );
        }
    }
}

/// `text` as XML 1.0 character data or an attribute value: `& < > " '` as entities, and
/// each character XML 1.0 forbids (the C0 controls but tab, newline and carriage return;
/// U+FFFE and U+FFFF) as U+FFFD, so that a name with a control character in it still gives
/// a well-formed SVG (and a PNG).
fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' | '\n' | '\r' => out.push(c),
            '\u{0}'..='\u{1f}' | '\u{fffe}' | '\u{ffff}' => out.push(char::REPLACEMENT_CHARACTER),
            c => out.push(c),
        }
    }
    out
}

/// Rasterises an SVG (such as [`plan_svg`]'s) to PNG bytes, with the system's fonts for
/// the labels.
///
/// # Errors
/// An SVG that cannot be read, a picture of no size, a PNG that cannot be encoded.
#[cfg(feature = "png")]
pub fn svg_to_png(svg: &str) -> Result<Vec<u8>, PictureError> {
    use resvg::{tiny_skia, usvg};
    let mut options = usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let tree = usvg::Tree::from_str(svg, &options)?;
    let size = tree.size().to_int_size();
    let mut pixmap =
        tiny_skia::Pixmap::new(size.width(), size.height()).ok_or(PictureError::NoSize)?;
    resvg::render(&tree, tiny_skia::Transform::default(), &mut pixmap.as_mut());
    pixmap
        .encode_png()
        .map_err(|e| PictureError::Png(e.to_string()))
}

/// Why a plan cannot be made a PNG.
#[cfg(feature = "png")]
#[derive(Debug, thiserror::Error)]
pub enum PictureError {
    /// The SVG cannot be read.
    #[error("cannot read the SVG: {0}")]
    Svg(#[from] resvg::usvg::Error),
    /// The picture has no pixels.
    #[error("the picture has no size")]
    NoSize,
    /// The PNG encoder failed.
    #[error("cannot encode the PNG: {0}")]
    Png(String),
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga::Multivector;

    #[test]
    fn footprint_of_a_turned_box() {
        let o = Object::new_box(
            "b",
            DVec3::new(2.0, 1.0, 1.0),
            DVec3::ZERO,
            glam::DQuat::from_rotation_y(std::f64::consts::FRAC_PI_4),
            1.0,
        )
        .unwrap();
        let f = footprint(&o);
        assert_eq!(f.len(), 4, "{f:?}");
        let area: f64 = (0..4).map(|i| f[i].perp_dot(f[(i + 1) % 4])).sum::<f64>() * 0.5;
        assert!((area.abs() - 2.0).abs() < 1e-9, "{area}");
    }

    #[test]
    fn plan_names_every_object_and_shows_the_edit() {
        let before = crate::examples::build("workshop").unwrap();
        let mut after = before.clone();
        let table = after.find("tool table").unwrap();
        after
            .apply(
                table,
                &Multivector::translator(DVec3::new(1.0, 0.0, 0.5)),
                true,
            )
            .unwrap();
        let svg = plan_svg(&after, Some(&before));
        for o in &after.objects {
            assert!(
                svg.contains(&format!(">{}</text>", escape(&o.name))),
                "{}",
                o.name
            );
        }
        let arrows = svg.matches("marker-end=\"url(#arrow)\"").count();
        assert_eq!(arrows, 4, "the table and the three tools on it moved");
        assert_eq!(svg.matches("stroke-dasharray=\"5,4\"").count(), 4);
        assert!(plan_svg(&before, None).matches("marker-end").count() == 0);
    }

    #[cfg(feature = "png")]
    #[test]
    fn png_is_a_real_picture() {
        let scene = crate::examples::build("living_room").unwrap();
        let png = svg_to_png(&plan_svg(&scene, None)).unwrap();
        assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
        let pixmap = resvg::tiny_skia::Pixmap::decode_png(&png).unwrap();
        assert_eq!(pixmap.width(), 1000);
        let coloured = pixmap
            .pixels()
            .iter()
            .filter(|p| p.red() != p.blue())
            .count();
        assert!(
            coloured > 10_000,
            "the plan has coloured shapes: {coloured} pixels"
        );
    }
}

#[cfg(test)]
mod label_tests {
    use super::*;

    #[test]
    fn names_with_control_characters_give_well_formed_xml() {
        let name = "a\u{1}b\u{1b}]0;pwned\u{7} <&> \"q\" 'x' \u{fffe}\u{ffff}\u{0}\tz";
        let mut scene = Scene::new(name);
        scene.push_box(name, [1.0, 1.0, 1.0], [0.0, 0.0, 0.0]);
        let svg = plan_svg(&scene, None);
        let document = roxmltree::Document::parse(&svg).unwrap_or_else(|e| panic!("{e}"));
        // The characters XML forbids became U+FFFD; the rest read back as they were.
        let shown = "a\u{fffd}b\u{fffd}]0;pwned\u{fffd} <&> \"q\" 'x' \u{fffd}\u{fffd}\u{fffd}\tz";
        let texts: Vec<String> = document
            .descendants()
            .filter_map(|n| n.text())
            .map(str::to_string)
            .collect();
        assert!(texts.iter().any(|t| t.contains(shown)), "{texts:?}");
        #[cfg(feature = "png")]
        {
            let png = svg_to_png(&svg).unwrap();
            assert!(png.starts_with(b"\x89PNG\r\n\x1a\n"));
        }
    }

    #[test]
    fn huge_names_are_cut_and_the_plan_stays_small() {
        let mut scene = Scene::new("t");
        scene.push_box(&"n".repeat(1_000_000), [1.0, 1.0, 1.0], [0.0, 0.0, 0.0]);
        scene.push_box("b", [1.0, 1.0, 1.0], [2.0, 0.0, 0.0]);
        let svg = plan_svg(&scene, None);
        assert!(svg.len() < 10_000, "{} bytes", svg.len());
        assert!(svg.contains('…'));
    }
}
