//! USD stages read and written: frames, op stacks, geometry, the layer, limits.

use super::*;
use crate::format::ReadOptions;
use glam::DQuat;

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

const ROOM_Z_UP_CM: &str = r#"#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 0.01
    upAxis = "Z"
)

def Xform "World"
{
    def Xform "Table"
    {
        double3 xformOp:translate = (100, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]

        def Cube "Top"
        {
            double size = 80
            double3 xformOp:translate = (0, 0, 40)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
    }

    def Xform "Shelf"
    {
        double3 xformOp:translate = (-200, 0, 0)
        float xformOp:rotateZ = 90
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateZ"]

        def Mesh "Body"
        {
            point3f[] points = [(-50, -10, 0), (50, -10, 0), (50, 10, 0), (-50, 10, 0), (-50, -10, 180), (50, -10, 180), (50, 10, 180), (-50, 10, 180)]
            int[] faceVertexCounts = [4]
            int[] faceVertexIndices = [0, 1, 2, 3]
        }
    }

    def Scope "Looks"
    {
    }
}
"#;

#[test]
fn a_z_up_centimetre_stage_reads_as_y_up_metres() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "room.usda", ROOM_Z_UP_CM);
    let (scene, document) = read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(document.frame.up, UpAxis::Z);
    assert_eq!(document.default_prim.as_deref(), Some("World"));
    let names: Vec<&str> = scene.objects.iter().map(|o| o.name.as_str()).collect();
    assert_eq!(names, ["Table", "Shelf"]);
    // The table's top: an 80 cm cube centred 40 cm up at x = 100 cm.
    let table = scene.objects[0].world_aabb();
    assert!(
        (table.min - DVec3::new(0.6, 0.0, -0.4)).length() < 1e-9,
        "{table:?}"
    );
    assert!(
        (table.max - DVec3::new(1.4, 0.8, 0.4)).length() < 1e-9,
        "{table:?}"
    );
    // The shelf, turned 90° about up: 1 m long along −z… its 20 cm depth along x.
    let shelf = scene.objects[1].world_aabb();
    assert!(
        (shelf.size() - DVec3::new(0.2, 1.8, 1.0)).length() < 1e-9,
        "{shelf:?}"
    );
    assert!((shelf.center().x + 2.0).abs() < 1e-9);
}

#[test]
fn an_edit_changes_only_the_moved_prims_op_stack() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "room.usda", ROOM_Z_UP_CM);
    let (mut scene, document) = read(&path, &ReadOptions::default()).unwrap();
    // Unchanged: the original bytes.
    assert_eq!(
        super::write(&scene, &document, UsdContainer::Usda, None).unwrap(),
        ROOM_Z_UP_CM.as_bytes()
    );
    // 0.5 m right (+x in both frames) and 0.3 m forward (Shenlong +z is the stage's −y).
    let m = cga::Multivector::translator(DVec3::new(0.5, 0.0, 0.3));
    scene.apply(1, &m, false).unwrap();
    let bytes = super::write(&scene, &document, UsdContainer::Usda, None).unwrap();
    let out = write(dir.path(), "out.usda", std::str::from_utf8(&bytes).unwrap());
    let (again, _) = read(&out, &ReadOptions::default()).unwrap();
    let before = scene.objects[1].world_aabb();
    let after = again.objects[1].world_aabb();
    assert!(
        (after.min - before.min).length() < 1e-9,
        "{before:?} {after:?}"
    );
    assert!(
        (again.objects[0].world_aabb().min - scene.objects[0].world_aabb().min).length() < 1e-12
    );
    let text = String::from_utf8(bytes).unwrap();
    // Only the shelf's lines changed: its order replaced, its new ops added; every other
    // line is the input's, in order.
    let removed: Vec<&str> = ROOM_Z_UP_CM
        .lines()
        .filter(|l| !text.lines().any(|t| t == *l))
        .collect();
    assert_eq!(
        removed,
        ["        uniform token[] xformOpOrder = [\"xformOp:translate\", \"xformOp:rotateZ\"]"]
    );
    let added: Vec<&str> = text
        .lines()
        .filter(|l| !ROOM_Z_UP_CM.lines().any(|t| t == *l))
        .collect();
    assert_eq!(added.len(), 4, "{added:?}");
    assert!(
        added[0].contains("double3 xformOp:translate:shenlong = (-150, -30, 0)"),
        "{added:?}"
    );
    assert!(
        added[1].contains(
            "quatd xformOp:orient:shenlong = (0.7071067811865476, 0, 0, 0.7071067811865475)"
        ) || added[1].contains("quatd xformOp:orient:shenlong"),
        "{added:?}"
    );
    // A .usdc output is refused, naming .usda.
    let e = super::write(&scene, &document, UsdContainer::Usdc, None).unwrap_err();
    assert!(e.to_string().contains(".usda"), "{}", e.to_string());
}

#[test]
fn written_elsewhere_asset_paths_still_resolve() {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "room.usda", ROOM_Z_UP_CM);
    let shot = write(
        dir.path(),
        "shot.usda",
        "#usda 1.0\n(\n    defaultPrim = \"World\"\n    metersPerUnit = 0.01\n    subLayers = [\n        @./room.usda@\n    ]\n    upAxis = \"Z\"\n)\n",
    );
    let (mut scene, document) = read(&shot, &ReadOptions::default()).unwrap();
    let table = scene.find("Table").unwrap();
    scene
        .apply(table, &cga::Multivector::translator(DVec3::X), false)
        .unwrap();
    let out_dir = dir.path().join("renders/v2");
    std::fs::create_dir_all(&out_dir).unwrap();
    let bytes = super::write(&scene, &document, UsdContainer::Usda, Some(&out_dir)).unwrap();
    let text = String::from_utf8(bytes).unwrap();
    assert!(text.contains("@../../room.usda@"), "{text}");
    // The table has no spec in the shot: an over for it.
    assert!(text.contains("over \"World\""), "{text}");
    let out = out_dir.join("shot.usda");
    std::fs::write(&out, &text).unwrap();
    // Read from there, every object is still composed (the stage's folder is the
    // output's, so read with the files outside it allowed by reading from their common
    // folder is what usd-core does; here the text is checked).
    assert!(
        text.contains("double3 xformOp:translate:shenlong = (200, 0, 0)"),
        "{text}"
    );
}

#[test]
fn the_layer_holds_only_overs_of_what_moved() {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "room.usda", ROOM_Z_UP_CM);
    let (mut scene, document) = read(&path, &ReadOptions::default()).unwrap();
    scene
        .apply(
            0,
            &cga::Multivector::translator(DVec3::new(-1.0, 0.0, 0.0)),
            false,
        )
        .unwrap();
    let layer = dir.path().join("edit.usda");
    let sub = sublayer_path(&path, &layer).unwrap();
    assert_eq!(sub, "./room.usda");
    let bytes = write_layer(&scene, &document, &sub).unwrap();
    let text = std::str::from_utf8(&bytes).unwrap();
    assert!(text.contains("over \"Table\""), "{text}");
    assert!(!text.contains("Shelf"), "{text}");
    std::fs::write(&layer, &bytes).unwrap();
    let (composed, _) = read(&layer, &ReadOptions::default()).unwrap();
    let moved = composed.objects[0].world_aabb();
    assert!((moved.min.x - (0.6 - 1.0)).abs() < 1e-9, "{moved:?}");
    // Never over its own source.
    assert!(sublayer_path(&path, &path).is_err());
}

#[test]
fn references_out_of_the_folder_and_deep_nesting_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let inner = dir.path().join("inner");
    std::fs::create_dir(&inner).unwrap();
    write(dir.path(), "secret.usda", ROOM_Z_UP_CM);
    let escaping = write(
        &inner,
        "room.usda",
        "#usda 1.0\n(\n    subLayers = [@../secret.usda@]\n)\n",
    );
    let e = read(&escaping, &ReadOptions::default())
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("secret.usda' is outside the stage's folder"),
        "{e}"
    );
    let absolute = write(
        &inner,
        "abs.usda",
        &format!(
            "#usda 1.0\ndef Xform \"A\" (\n    references = @{}@\n)\n{{\n}}\n",
            dir.path().join("secret.usda").display()
        ),
    );
    let e = read(&absolute, &ReadOptions::default())
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("is outside the stage's folder"), "{e}");
    let deep = format!("#usda 1.0\n{}", "(".repeat(200));
    let deep = write(dir.path(), "deep.usda", &deep);
    let e = read(&deep, &ReadOptions::default())
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.contains("nesting deeper than"), "{e}");
}

#[test]
fn a_local_transform_that_is_no_trs_is_written_as_a_matrix() {
    let shear = DMat4::from_cols_array(&[
        1.0, 0.0, 0.0, 0.0, 0.5, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
    ]);
    let ops = ops_for(shear);
    assert_eq!(ops.len(), 1);
    assert_eq!(ops[0].0, "xformOp:transform:shenlong");
    let trs = DMat4::from_scale_rotation_translation(
        DVec3::splat(2.0),
        DQuat::from_rotation_y(0.3),
        DVec3::new(1.0, 2.0, 3.0),
    );
    assert_eq!(ops_for(trs).len(), 3);
}

#[test]
fn a_scene_from_elsewhere_is_written_as_a_new_stage_and_read_back() {
    let scene = crate::examples::build("living_room").unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("lr.usda");
    std::fs::write(&path, write_new(&scene)).unwrap();
    let (again, document) = read(&path, &ReadOptions::default()).unwrap();
    assert_eq!(document.frame.up, UpAxis::Y);
    assert_eq!(again.objects.len(), scene.objects.len());
    for (a, b) in scene.objects.iter().zip(&again.objects) {
        assert_eq!(a.name, b.name);
        let (x, y) = (a.world_aabb(), b.world_aabb());
        assert!(
            (x.min - y.min).length() < 1e-9 && (x.max - y.max).length() < 1e-9,
            "{}",
            a.name
        );
    }
    let mut names = Identifiers::default();
    assert_eq!(names.make("2 chairs"), "_2_chairs");
    assert_eq!(names.make("a_b"), "a_b");
    assert_eq!(names.make("a-b"), "a_b_2");
    assert_eq!(names.make("a b"), "a_b_3");
    // Thousands of names that become one: each a few look-ups, not a scan.
    let many: Vec<String> = (0..5000).map(|_| names.make("x?")).collect();
    assert_eq!(many[4999], "x__5000");
}

#[test]
fn every_example_reads_back_the_same_from_usd_and_gltf() {
    // No format loses a fact another has: the same objects, boxes, fronts, supports and
    // room from a new USD stage and a new glTF as from scene JSON.
    let dir = tempfile::tempdir().unwrap();
    for (name, _) in crate::examples::list() {
        let scene = crate::examples::build(name).unwrap();
        let usd = write(
            dir.path(),
            &format!("{name}.usda"),
            std::str::from_utf8(&write_new(&scene)).unwrap(),
        );
        let (from_usd, _) = read(&usd, &ReadOptions::default()).unwrap();
        let glb = super::super::gltf_new::write_new(&scene, true).unwrap();
        let (from_gltf, _) = super::super::gltf::read_bytes(glb, Path::new("."), name).unwrap();
        for back in [&from_usd, &from_gltf] {
            assert_eq!(back.objects.len(), scene.objects.len(), "{name}");
            for (a, b) in scene.objects.iter().zip(&back.objects) {
                assert_eq!(a.name, b.name, "{name}");
                let (x, y) = (a.world_aabb(), b.world_aabb());
                assert!(
                    (x.min - y.min).length() < 1e-5 && (x.max - y.max).length() < 1e-5,
                    "{name}: {}",
                    a.name
                );
                assert!(
                    (a.world_front() - b.world_front()).length() < 1e-6,
                    "{name}: {} front",
                    a.name
                );
                assert_eq!(a.labels.category, b.labels.category, "{name}: {}", a.name);
                let support = |s: &crate::scene::Scene, o: &crate::scene::Object| {
                    o.support.map(|k| s.objects[k].name.clone())
                };
                assert_eq!(
                    support(&scene, a),
                    support(back, b),
                    "{name}: {} support",
                    a.name
                );
            }
            let (ra, rb) = (scene.bounds.unwrap(), back.bounds.unwrap());
            assert!(
                (ra.min - rb.min).length() < 1e-5 && (ra.max - rb.max).length() < 1e-5,
                "{name}: {ra:?} {rb:?}"
            );
        }
    }
}

#[test]
fn fronts_follow_each_prims_turn_its_own_front_and_the_runs_axis() {
    // Blender's convention: Z-up models face −Y. An armchair turned rotateZ −90 faces −X;
    // a lamp with its own `shenlong:front` (+X in its axes) faces +X; a stool faces +Z.
    let stage = r#"#usda 1.0
(
    defaultPrim = "root"
    metersPerUnit = 0.01
    upAxis = "Z"
)

def Xform "root"
{
    def Xform "Armchair"
    {
        float xformOp:rotateZ = -90
        uniform token[] xformOpOrder = ["xformOp:rotateZ"]
        def Cube "Body"
        {
            double size = 80
        }
    }

    def Xform "Lamp"
    {
        custom double3 shenlong:front = (1, 0, 0)
        double3 xformOp:translate = (300, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        def Cube "Body"
        {
            double size = 30
        }
    }

    def Xform "Stool"
    {
        double3 xformOp:translate = (-300, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        def Cube "Body"
        {
            double size = 40
        }
    }
}
"#;
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "fronts.usda", stage);
    let (scene, _) = read(&path, &ReadOptions::default()).unwrap();
    let front = |name: &str| scene.objects[scene.find(name).unwrap()].world_front();
    assert!(
        (front("Armchair") - DVec3::NEG_X).length() < 1e-9,
        "{}",
        front("Armchair")
    );
    assert!((front("Lamp") - DVec3::X).length() < 1e-9);
    assert!((front("Stool") - DVec3::Z).length() < 1e-9);
    // A file that follows another convention: its models face +X (in its axes).
    let options = ReadOptions {
        front: Some("+x".parse().unwrap()),
        ..ReadOptions::default()
    };
    let (scene, _) = read(&path, &options).unwrap();
    let front = |name: &str| scene.objects[scene.find(name).unwrap()].world_front();
    // +X turned −90° about Z is −Y in the stage: Shenlong's +Z.
    assert!(
        (front("Armchair") - DVec3::Z).length() < 1e-9,
        "{}",
        front("Armchair")
    );
    assert!(
        (front("Lamp") - DVec3::X).length() < 1e-9,
        "a prim's own front wins"
    );
    assert!((front("Stool") - DVec3::X).length() < 1e-9);
}

#[test]
fn names_with_quotes_and_backslashes_survive_round_trips() {
    // Written escaped, read unescaped: a name gains no backslash however often it goes
    // through a stage.
    let mut scene = crate::scene::Scene::new("q");
    scene.push_box(r#"quote"inside\and back"#, [1.0; 3], [0.0; 3]);
    let dir = tempfile::tempdir().unwrap();
    for round in 0..3 {
        let path = write(
            dir.path(),
            &format!("q{round}.usda"),
            std::str::from_utf8(&write_new(&scene)).unwrap(),
        );
        scene = read(&path, &ReadOptions::default()).unwrap().0;
        assert_eq!(
            scene.objects[0].name, r#"quote"inside\and back"#,
            "round {round}"
        );
    }
}

/// A stage exercising every op kind, kinds, inactive prims, float precision and Shenlong's
/// own attributes: what both readers must read alike.
const EVERY_OP: &str = r#"#usda 1.0
(
    "A layer with a doc string"
    defaultPrim = "World"
    metersPerUnit = 0.0254
    upAxis = "Z"
    customLayerData = {
        string creator = "Blender v4.2"
        dictionary nested = { int a = 1 }
    }
)

def Xform "World" (
    kind = "assembly"
)
{
    def Xform "Lamp" (
        kind = "component"
        prepend apiSchemas = ["MaterialBindingAPI"]
        doc = """a "lamp" (with parentheses)"""
    )
    {
        custom string shenlong:name = "desk \"lamp\""
        custom string shenlong:category = "lamp"
        custom double3 shenlong:front = (0, -1, 0)
        float3 xformOp:translate = (1.1, 2.2, 3.3)
        float3 xformOp:rotateXYZ:tilt = (10, 20, 30)
        quatf xformOp:orient = (0.9238795, 0, 0, 0.3826834)
        half3 xformOp:scale = (1, 2, 0.5)
        double xformOp:rotateY = 45
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ:tilt", "xformOp:orient", "!invert!xformOp:rotateY", "xformOp:scale"]
        rel material:binding = </World/Looks/Brass>

        def Mesh "Shade" (
            active = true
        )
        {
            point3f[] points = [(-1, -1, 0), (1, -1, 0), (1, 1, 2.5), (-1, 1, 2.5)] (
                interpolation = "vertex"
            )
            int[] faceVertexCounts = [4]
            int[] faceVertexIndices = [0, 1, 2, 3]
            texCoord2f[] primvars:st = [(0, 0), (1, 0), (1, 1), (0, 1)]
        }
        def Cylinder "Pole"
        {
            double radius = 0.25
            double height = 3
            uniform token axis = "Y"
        }
    }

    def Xform "Frame" (
        kind = "component"
    )
    {
        matrix4d xformOp:transform = ( (0, 1, 0, 0), (-1, 0, 0, 0), (0, 0, 1, 0), (5, 6, 7, 1) )
        uniform token[] xformOpOrder = ["xformOp:transform"]

        def Xform "Loose"
        {
            double3 xformOp:translate = (1, 1, 1)
            uniform token[] xformOpOrder = ["!resetXformStack!", "xformOp:translate"]

            def Sphere "Ball"
            {
                double radius = 0.5
            }
        }
        def Capsule "Pill"
        {
            double radius = 0.2
            double height = 1
            uniform token axis = "X"
            float3[] extent = [(-0.7, -0.2, -0.2), (0.7, 0.2, 0.2)]
        }
    }

    def Xform "Gone" (
        active = false
        kind = "component"
    )
    {
        def Cube "Box"
        {
        }
    }

    def Scope "Looks"
    {
        def Material "Brass"
        {
            token outputs:surface.connect = </World/Looks/Brass/Shader.outputs:surface>
        }
    }

    def "Untyped"
    {
        def BasisCurves "Wire"
        {
            float3[] extent = [(0, 0, 0), (1, 2, 3)]
        }
    }
}

def Xform "Elsewhere"
{
    def Cube "Lost"
    {
    }
}
"#;

/// The walk of a `.usda` by both readers: (the composing reader's, Shenlong's own).
fn both_walks(text: &str, options: &ReadOptions) -> (wire::Walked, Option<wire::Walked>) {
    let dir = tempfile::tempdir().unwrap();
    let path = write(dir.path(), "stage.usda", text);
    let composed = walk(&path, options).unwrap();
    let own = own_walk(&path, UsdContainer::Usda, options).unwrap();
    (composed, own)
}

/// Whether two walks agree, to 1e-9 in every number.
fn assert_same_walk(a: &wire::Walked, b: &wire::Walked) {
    let near = |x: &DMat4, y: &DMat4| {
        x.to_cols_array()
            .iter()
            .zip(y.to_cols_array())
            .all(|(p, q)| (p - q).abs() <= 1e-9 * (1.0 + p.abs()))
    };
    assert_eq!(a.frame, b.frame);
    assert_eq!(a.default_prim, b.default_prim);
    assert_eq!(a.tree.nodes.len(), b.tree.nodes.len());
    for (m, n) in a.tree.nodes.iter().zip(&b.tree.nodes) {
        assert_eq!(
            (&m.name, m.parent, m.transformable, m.model),
            (&n.name, n.parent, n.transformable, n.model),
            "{}",
            m.fallback
        );
        assert_eq!(
            (&m.given_name, &m.labels.category, &m.fallback),
            (&n.given_name, &n.labels.category, &n.fallback)
        );
        assert!(near(&m.world, &n.world), "{}", m.fallback);
        assert_eq!(m.points.len(), n.points.len(), "{}", m.fallback);
        for (p, q) in m.points.iter().zip(&n.points) {
            assert!((*p - *q).length() < 1e-9, "{}: {p} {q}", m.fallback);
        }
        assert_eq!(m.triangles, n.triangles, "{}", m.fallback);
        assert_eq!(m.front.is_some(), n.front.is_some());
        if let (Some(f), Some(g)) = (m.front, n.front) {
            assert!((f - g).length() < 1e-12);
        }
    }
    for (p, q) in a.prims.iter().zip(&b.prims) {
        assert_eq!((&p.path, p.resets), (&q.path, q.resets));
        assert!(near(&p.world, &q.world) && near(&p.parent_world, &q.parent_world));
    }
}

#[test]
fn the_own_layer_reader_reads_as_the_composing_one() {
    let examples = write_new(&crate::examples::build("living_room").unwrap());
    let stages = [
        EVERY_OP.to_string(),
        ROOM_Z_UP_CM.to_string(),
        String::from_utf8(examples).unwrap(),
        // No default prim: every root prim, and USD's fallback frame.
        EVERY_OP
            .replace("    defaultPrim = \"World\"\n", "")
            .replace("    upAxis = \"Z\"\n", "")
            .replace("    metersPerUnit = 0.0254\n", ""),
        // No component: objects are the default prim's children.
        EVERY_OP.replace("kind = \"component\"", "kind = \"group\""),
    ];
    for (k, text) in stages.iter().enumerate() {
        for units in [None, Some(crate::format::facts::Units::Centimetres)] {
            let options = ReadOptions {
                units,
                ..ReadOptions::default()
            };
            let (composed, own) = both_walks(text, &options);
            let own = own.unwrap_or_else(|| panic!("stage {k} was left to composition"));
            assert!(composed.tree.nodes.len() > 3, "stage {k}");
            assert_same_walk(&composed, &own);
        }
    }
}

#[test]
fn layers_that_compose_are_left_to_the_composing_reader() {
    let arcs = [
        (
            "    defaultPrim",
            "    subLayers = [@./other.usda@]\n    defaultPrim",
        ),
        ("kind = \"assembly\"", "references = @./other.usda@</X>"),
        ("kind = \"assembly\"", "prepend payload = @./other.usda@"),
        ("kind = \"assembly\"", "inherits = </Base>"),
        ("kind = \"assembly\"", "append specializes = </Base>"),
        (
            "kind = \"assembly\"",
            "variants = { string look = \"red\" }",
        ),
        ("def Xform \"Elsewhere\"", "over \"Elsewhere\""),
        ("def Xform \"Elsewhere\"", "class Xform \"Elsewhere\""),
        (
            "double radius = 0.25",
            "double radius.timeSamples = { 0: 1, 10: 2 }",
        ),
        (
            "float3 xformOp:translate = (1.1, 2.2, 3.3)",
            "float3 xformOp:translate.timeSamples = { 0: (1, 2, 3) }",
        ),
        (
            "uniform token axis = \"Y\"",
            "variantSet \"look\" = { \"red\" { } }",
        ),
        ("#usda 1.0", "#sdf 1.0"),
    ];
    let dir = tempfile::tempdir().unwrap();
    for (from, to) in arcs {
        assert!(EVERY_OP.contains(from), "{from}");
        let path = write(dir.path(), "stage.usda", &EVERY_OP.replacen(from, to, 1));
        let own = own_walk(&path, UsdContainer::Usda, &ReadOptions::default()).unwrap();
        assert!(own.is_none(), "read itself with {to}");
    }
    // A default prim that is no root prim: composition says what that means.
    let path = write(
        dir.path(),
        "stage.usda",
        &EVERY_OP.replace("defaultPrim = \"World\"", "defaultPrim = \"Nowhere\""),
    );
    assert!(own_walk(&path, UsdContainer::Usda, &ReadOptions::default())
        .unwrap()
        .is_none());
}

#[test]
fn the_own_layer_reader_bounds_depth_and_prims() {
    let mut deep = String::from("#usda 1.0\n");
    for k in 0..(crate::format::MAX_JSON_DEPTH + 2) {
        deep.push_str(&format!("def Xform \"P{k}\" {{\n"));
    }
    deep.push_str(&"}\n".repeat(crate::format::MAX_JSON_DEPTH + 2));
    let e = layer::read(&deep, 1_000).unwrap_err();
    assert!(
        e.to_string().contains("nesting deeper than"),
        "{}",
        e.to_string()
    );
    let many = format!("#usda 1.0\n{}", "def Xform \"A\" {}\n".repeat(20));
    let e = layer::read(&many, 10).unwrap_err();
    assert!(
        e.to_string().contains("more than 10 prims"),
        "{}",
        e.to_string()
    );
    // Whatever bytes it meets, it answers (the fuzz target runs it too).
    for text in [
        "#usda 1.0\ndef \"A\" { double3 xformOp:translate = (",
        "#usda 1.0\n}",
        "#usda 1.0\ndef X \"A\" ( kind = ) {}",
    ] {
        assert!(
            matches!(layer::read(text, 10), Ok(layer::Parsed::Compose)),
            "{text}"
        );
    }
}

/// A `Mesh` prim named `name` at `at` (stage units) made of the boxes `parts`, each a quad
/// per face.
fn mesh_prim(name: &str, at: [f64; 3], parts: &[([f64; 3], [f64; 3])]) -> String {
    use crate::scene::mesh::boxes;
    let (mut points, mut indices) = (Vec::new(), Vec::new());
    for (lo, hi) in parts {
        let base = points.len();
        for p in boxes::corners(*lo, *hi) {
            points.push(format!("({}, {}, {})", p.x, p.y, p.z));
        }
        for f in boxes::QUADS {
            indices.extend(f.map(|i| (base + i as usize).to_string()));
        }
    }
    format!(
        "    def Mesh \"{name}\"\n    {{\n        double3 xformOp:translate = ({}, {}, {})\n        uniform token[] xformOpOrder = [\"xformOp:translate\"]\n        point3f[] points = [{}]\n        int[] faceVertexCounts = [{}]\n        int[] faceVertexIndices = [{}]\n    }}\n",
        at[0],
        at[1],
        at[2],
        points.join(", "),
        vec!["4"; parts.len() * 6].join(", "),
        indices.join(", ")
    )
}

#[test]
fn a_meshs_faces_give_its_shape_by_both_readers() {
    // Z up, centimetres: a desk whose 4 cm top is 72 cm up on four legs, and a crate open
    // at the top.
    let mut desk: Vec<([f64; 3], [f64; 3])> =
        [(0.0, 0.0), (115.0, 0.0), (0.0, 65.0), (115.0, 65.0)]
            .map(|(x, y)| ([x, y, 0.0], [x + 5.0, y + 5.0, 72.0]))
            .to_vec();
    desk.push(([0.0, 0.0, 72.0], [120.0, 70.0, 76.0]));
    let crate_parts = [
        ([0.0, 0.0, 0.0], [50.0, 40.0, 2.0]),
        ([0.0, 0.0, 0.0], [2.0, 40.0, 30.0]),
        ([48.0, 0.0, 0.0], [50.0, 40.0, 30.0]),
        ([0.0, 0.0, 0.0], [50.0, 2.0, 30.0]),
        ([0.0, 38.0, 0.0], [50.0, 40.0, 30.0]),
    ];
    let text = format!(
        "#usda 1.0\n(\n    defaultPrim = \"World\"\n    upAxis = \"Z\"\n    metersPerUnit = 0.01\n)\n\ndef Xform \"World\"\n{{\n{}{}}}\n",
        mesh_prim("Desk", [0.0, 0.0, 0.0], &desk),
        mesh_prim("Crate", [-200.0, 0.0, 0.0], &crate_parts)
    );
    let (composed, own) = both_walks(&text, &ReadOptions::default());
    let own = own.expect("read by Shenlong's own reader");
    assert_same_walk(&composed, &own);
    assert_eq!(composed.tree.nodes[1].triangles.len(), 5 * 6 * 2);
    let dir = tempfile::tempdir().unwrap();
    let file = crate::format::SceneFile::load(&write(dir.path(), "room.usda", &text)).unwrap();
    let scene = &file.scene;
    let form = |name: &str| crate::ground::kind::form_of(scene, scene.find(name).unwrap());
    assert_eq!(
        form("Desk"),
        crate::scene::Form::OnLegs {
            underside: Some(947)
        }
    );
    assert_eq!(form("Crate"), crate::scene::Form::Open);
}
