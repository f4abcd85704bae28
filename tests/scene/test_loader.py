"""TOML scene files: values, transforms, relative paths, errors with key and line, round trips."""

from __future__ import annotations

import json
import math
import textwrap

import numpy as np
import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from pixelpath.scene import (
    Box,
    Camera,
    DirectionalLight,
    Material,
    Mesh,
    Plane,
    PointLight,
    Scene,
    Sphere,
    bundled_scenes,
    load_scene,
    transform_matrix,
)

SCENE = textwrap.dedent(
    """\
    # a small scene using every kind of object
    ambient = [0.1, 0.2, 0.3]
    background = [0.0, 0.0, 0.25]

    [camera]
    eye = [0, 2, 10]
    target = [0, 0, 0]
    fov = 40
    width = 64
    height = 48

    [[lights]]
    type = "point"
    position = [5, 5, 5]
    intensity = 0.8

    [[lights]]
    type = "directional"
    direction = [0, -3, -4]
    color = [1, 0.5, 0.25]

    [materials.red]
    color = [0.9, 0.1, 0.1]
    ks = 0.5

    [[objects]]
    type = "sphere"
    center = [1, 0, 0]
    radius = 1
    material = "red"
    transform = { rotate = [0, 0, 90], scale = 2 }

    [[objects]]
    type = "plane"
    point = [0, 0, 0]
    normal = [0, 1, 0]
    material = { color = [0.5, 0.5, 0.5], kd = 0.9 }
    transform = { translate = [0, -1, 0] }

    [[objects]]
    type = "box"
    minimum = [0, 0, 0]
    maximum = [1, 2, 3]
    transform = { translate = [1, 1, 1], scale = [2, -1, 1] }

    [[objects]]
    type = "box"
    minimum = [-1, -1, -1]
    maximum = [1, 1, 1]
    transform = { rotate = [0, 45, 0] }

    [[objects]]
    type = "mesh"
    path = "meshes/cube.obj"
    name = "cube"
    transform = { translate = [0, 0, -5], scale = 0.5 }

    [[objects]]
    type = "icosphere"
    subdivisions = 1
    radius = 0.5

    [[objects]]
    type = "torus"
    major_radius = 2
    minor_radius = 0.5
    major_segments = 8
    minor_segments = 4
    material = "red"
    """
)
CUBE_OBJ = textwrap.dedent(
    """\
    v 0 0 0
    v 1 0 0
    v 1 1 0
    v 0 1 0
    v 0 0 1
    v 1 0 1
    v 1 1 1
    v 0 1 1
    f 1 4 3 2
    f 5 6 7 8
    f 1 2 6 5
    f 3 4 8 7
    f 2 3 7 6
    f 1 5 8 4
    """
)


@pytest.fixture
def scene_file(tmp_path):
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "cube.obj").write_text(CUBE_OBJ)
    path = tmp_path / "scene.toml"
    path.write_text(SCENE)
    return path


def written(tmp_path, text: str):
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return path


def test_scene_values(scene_file, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path.parent)  # mesh paths are relative to the file, not the cwd
    scene = load_scene(scene_file)
    assert scene.camera == Camera(eye=(0, 2, 10), target=(0, 0, 0), fov=40, width=64, height=48)
    np.testing.assert_array_equal(scene.ambient, [0.1, 0.2, 0.3])
    np.testing.assert_array_equal(scene.background, [0, 0, 0.25])
    point, sun = scene.lights
    assert point == PointLight((5, 5, 5), intensity=0.8)
    assert sun == DirectionalLight((0, -0.6, -0.8), color=(1, 0.5, 0.25))
    red = Material(color=(0.9, 0.1, 0.1), ks=0.5)
    assert scene.objects[0].material == red and scene.objects[0].material.name == "red"
    assert scene.objects[6].material is scene.objects[0].material
    assert scene.objects[1].material == Material(color=(0.5, 0.5, 0.5), kd=0.9)
    assert [type(obj) for obj in scene.objects] == [Sphere, Plane, Box, Mesh, Mesh, Mesh, Mesh]


def test_transforms_of_each_kind(scene_file):
    sphere, plane, box, turned_box, cube, ball, ring = load_scene(scene_file).objects
    # centre (1, 0, 0) scaled by 2 -> (2, 0, 0), turned 90° about Z -> (0, 2, 0)
    np.testing.assert_allclose(sphere.center, [0, 2, 0], atol=1e-15)
    assert sphere.radius == 2.0
    np.testing.assert_array_equal(plane.point, [0, -1, 0])
    np.testing.assert_array_equal(plane.normal, [0, 1, 0])
    # corners (0,0,0), (1,2,3) scaled by (2,-1,1) then moved by (1,1,1): (1,1,1), (3,-1,4)
    np.testing.assert_array_equal(box.bounds(), [[1, -1, 1], [3, 1, 4]])
    # the unit-radius cube turned 45° about Y reaches ±√2 along X and Z
    r = math.sqrt(2)
    np.testing.assert_allclose(turned_box.bounds(), [[-r, -1, -r], [r, 1, r]], atol=1e-12)
    assert turned_box.face_count == 6
    assert cube.name == "cube" and cube.face_count == 6
    np.testing.assert_allclose(cube.bounds(), [[0, 0, -5], [0.5, 0.5, -4.5]])
    assert len(ball.vertices) == 42
    np.testing.assert_allclose(ring.bounds(), [[-2.5, -0.5, -2.5], [2.5, 0.5, 2.5]], atol=1e-12)


def test_transform_matrix_order_scale_then_x_y_z_then_translate():
    # X first: (0,1,0) -> (0,0,1); then Y: (0,0,1) -> (1,0,0). The other order gives (0,0,1).
    np.testing.assert_allclose(transform_matrix(rotate=(90, 90, 0)) @ [0, 1, 0, 1], [1, 0, 0, 1],
                               atol=1e-15)
    # scale first: (1,0,0) -> (2,0,0), then 90° about Z -> (0,2,0), then moved
    matrix = transform_matrix(translate=(1, 2, 3), rotate=(0, 0, 90), scale=(2, 1, 1))
    np.testing.assert_allclose(matrix @ [1, 0, 0, 1], [1, 4, 3, 1], atol=1e-15)
    np.testing.assert_array_equal(transform_matrix(), np.eye(4))
    with pytest.raises(ValueError, match="scale factors must be non-zero"):
        transform_matrix(scale=(1, 0, 1))


@pytest.mark.parametrize(
    ("old", "new", "error", "message"),
    [
        ("radius = 1\n", "radius = 1\nradious = 2\n", ValueError,
         r"objects\[0\]\.radious \(near line 30\): unknown key; expected one of: center, "),
        ("radius = 1\n", "radius = -1\n", ValueError,
         r"objects\[0\]\.radius \(near line 29\): radius must be positive, got -1.0"),
        ("radius = 1\n", 'radius = "big"\n', ValueError,
         r"objects\[0\]\.radius \(near line 29\): expected a number, got 'big'"),
        ('material = "red"', 'material = "gold"', ValueError,
         r"objects\[0\]\.material \(near line 30\): unknown material 'gold'; defined mat"),
        ("fov = 40", "fov = 180", ValueError, r"camera\.fov \(near line 8\): fov"),
        ("width = 64", "width = 100000", ValueError,
         r"camera\.width \(near line 9\): width must be between 1 and 16384"),
        ("eye = [0, 2, 10]\n", "", ValueError, r"camera \(near line 5\): missing key 'eye'"),
        ("eye = [0, 2, 10]", "eye = [0, 2]", ValueError,
         r"camera\.eye \(near line 6\): expected an array of 3 numbers"),
        ("eye = [0, 2, 10]", "eye = [0, 0, 0]", ValueError,
         r"camera\.eye \(near line 6\): eye and target must differ"),
        ('type = "torus"', 'type = "donut"', ValueError,
         r"objects\[6\]\.type \(near line 64\): unknown type 'donut'; expected 'sphere'"),
        ("intensity = 0.8", "intensity = 0.8\nfalloff = 2", ValueError,
         r"lights\[0\]\.falloff \(near line 16\): unknown key"),
        ("ks = 0.5", "ks = 0.5\nspecular = 1", ValueError,
         r"materials\.red\.specular \(near line 25\): unknown key"),
        ("rotate = [0, 45, 0]", "rotation = [0, 45, 0]", ValueError,
         r"objects\[3\]\.transform\.rotation \(near line 50\): unknown key; expected one of: rot"),
        ("scale = 2 }", "scale = [1, 2, 1] }", ValueError,
         r"objects\[0\]\.transform \(near line 31\): transform must scale a sphere uniformly"),
        ("ambient = [0.1, 0.2, 0.3]", "ambient = -1", ValueError,
         r"ambient \(near line 2\): ambient components must be non-negative"),
        ("cube.obj", "sphere.obj", FileNotFoundError,
         r"objects\[4\]\.path \(near line 54\): mesh file not found: .*meshes/sphere\.obj"),
        ("subdivisions = 1", "subdivisions = 9", ValueError,
         r"objects\[5\]\.subdivisions \(near line 60\): subdivisions must be between 0 and 7"),
        ('path = "meshes/cube.obj"', 'path = "meshes/cube.obj"\nvertices = [[0, 0, 0]]', ValueError,
         r"objects\[4\] \(near line 52\): a mesh needs either 'path' or both 'vertices' and"),
        ("fov = 40", "fov = = 40", ValueError, r"invalid TOML: .*\(at line 8, column 7\)"),
    ],
)
def test_errors_name_file_key_line_and_expectation(scene_file, old, new, error, message):
    assert old in SCENE
    scene_file.write_text(SCENE.replace(old, new, 1))
    with pytest.raises(error, match=message) as raised:
        load_scene(scene_file)
    assert str(raised.value).startswith(str(scene_file))


def test_unknown_top_level_key_and_missing_camera(tmp_path):
    with pytest.raises(ValueError, match=r"gamma \(near line 1\): unknown key; expected one of"):
        load_scene(written(tmp_path, "gamma = 2.2\n" + SCENE))
    with pytest.raises(ValueError, match=r"scene.toml: \(top level\): missing key 'camera'"):
        load_scene(written(tmp_path, "ambient = 0.5\n"))


def test_inline_mesh_errors_name_the_object(tmp_path):
    text = SCENE.split("[[objects]]")[0] + textwrap.dedent(
        """\
        [[objects]]
        type = "mesh"
        vertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
        faces = [[0, 1, 5]]
        """
    )
    with pytest.raises(ValueError, match=r"objects\[0\]\.faces \(near line 29\): face 0 refers"):
        load_scene(written(tmp_path, text))
    with pytest.raises(ValueError, match=r"objects\[0\]\.vertices \(near line 28\): expected"):
        load_scene(written(tmp_path, text.replace("[0, 1, 0]]", "[0, 1]]")))


def test_missing_scene_file(tmp_path):
    with pytest.raises(FileNotFoundError, match=r"scene file not found: .*nothing\.toml"):
        load_scene(tmp_path / "nothing.toml")


def test_a_picture_or_a_folder_is_named_as_what_it_is(tmp_path):
    (tmp_path / "photo.jpg").write_bytes(b"\xff\xd8\xff\xe0 not text")
    with pytest.raises(ValueError, match=r"photo\.jpg: not a UTF-8 text file .*not a TOML scene "
                                         r"file; model files .*\.glb, \.gltf, \.obj, \.ply, \.stl"):
        load_scene(tmp_path / "photo.jpg")
    with pytest.raises(ValueError, match=r"is a folder; name a scene or model file in it"):
        load_scene(tmp_path)


def test_empty_scene_file_with_only_a_camera_loads(tmp_path):
    scene = load_scene(written(tmp_path, '[camera]\neye = [0, 0, 1]\ntarget = [0, 0, 0]\n'))
    assert scene.objects == () and scene.lights == ()


def test_file_round_trip_keeps_paths_relative_and_generators_compact(scene_file):
    scene = load_scene(scene_file)
    data = scene.to_dict(base_dir=scene_file.parent)
    assert json.loads(json.dumps(data)) == data  # plain JSON-compatible values only
    cube = data["objects"][4]
    assert cube == {"type": "mesh", "path": "meshes/cube.obj", "name": "cube",
                    "transform": {"translate": [0, 0, -5], "scale": 0.5}}
    assert data["objects"][6]["type"] == "torus" and "vertices" not in data["objects"][6]
    assert data["materials"]["red"]["ks"] == 0.5
    assert Scene.from_dict(data, base_dir=scene_file.parent) == scene


def test_dicts_validate_against_the_published_schema(scene_file):
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    from pixelpath.scene.schema import scene_json_schema

    schema = scene_json_schema()
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.validate(tomllib.loads(SCENE), schema)
    jsonschema.validate(load_scene(scene_file).to_dict(), schema)
    bad = tomllib.loads(SCENE.replace("radius = 1\n", "radious = 1\n"))
    with pytest.raises(jsonschema.ValidationError):
        jsonschema.validate(bad, schema)


unit = st.floats(0, 1)
coordinate = st.floats(-50, 50)
vectors = st.tuples(coordinate, coordinate, coordinate)
colours = st.tuples(unit, unit, unit)
materials = st.builds(
    Material, color=colours, ka=unit, kd=unit, ks=unit, shininess=st.floats(0, 200),
    reflectivity=unit, transparency=unit, ior=st.floats(0.5, 3),
    name=st.none() | st.sampled_from(["red", "glass"]),
    alpha=unit, alpha_cutoff=st.none() | st.floats(0, 2),
)  # fmt: skip


@st.composite
def cameras(draw):
    target = np.array(draw(vectors))
    offset = np.array(draw(vectors))
    assume(np.linalg.norm(np.cross(offset, [0, 1, 0])) > 1e-3)
    return Camera(eye=target + offset, target=target, fov=draw(st.floats(1, 170)),
                  width=draw(st.integers(1, 4096)), height=draw(st.integers(1, 4096)))


@st.composite
def boxes(draw):
    low = np.array(draw(vectors))
    size = np.array(draw(st.tuples(*[st.floats(0.01, 10)] * 3)))
    return Box(low, low + size, draw(materials))


@st.composite
def meshes(draw):
    count = draw(st.integers(3, 6))
    vertices = draw(st.lists(vectors, min_size=count, max_size=count))
    faces = [list(range(count)), [0, 1, 2]]
    normals = draw(st.none() | st.just([[0.0, 0.3, 1.0]] * count))
    return Mesh(vertices, faces, draw(materials), normals, name=draw(st.none() | st.just("m")))


def nonzero(vector) -> bool:
    return np.linalg.norm(vector) > 1e-6


objects = st.one_of(
    st.builds(Sphere, vectors, st.floats(0.01, 10), materials),
    st.builds(Plane, vectors, vectors.filter(nonzero), materials),
    boxes(),
    meshes(),
)
lights = st.one_of(
    st.builds(PointLight, vectors, st.floats(0, 5), colours),
    st.builds(DirectionalLight, vectors.filter(nonzero), st.floats(0, 5), colours),
)


@settings(max_examples=60, deadline=None)
@given(
    camera=cameras(),
    things=st.lists(objects, max_size=4),
    lamps=st.lists(lights, max_size=3),
    ambient=unit | colours,
    background=colours,
)
def test_to_dict_from_dict_round_trip(camera, things, lamps, ambient, background):
    scene = Scene(camera, things, lamps, ambient, background)
    data = json.loads(json.dumps(scene.to_dict()))
    assert Scene.from_dict(data) == scene


def test_bundled_scenes_load():
    scenes = bundled_scenes()
    if not scenes:
        pytest.skip("no bundled scenes in this checkout")
    for name, path in scenes.items():
        scene = load_scene(path)
        assert scene.objects, f"bundled scene {name} has no objects"


def test_bundled_scenes_follow_the_published_schema():
    jsonschema = pytest.importorskip("jsonschema")
    import tomllib

    from pixelpath.scene.schema import scene_json_schema

    for path in bundled_scenes().values():
        jsonschema.validate(tomllib.loads(path.read_text()), scene_json_schema())


def test_encoding_is_read_written_back_and_checked(tmp_path):
    camera = '[camera]\neye = [0, 0, 5]\ntarget = [0, 0, 0]\n'
    path = tmp_path / "s.toml"
    path.write_text(camera)
    plain = load_scene(path)
    assert plain.encoding == "linear" and "encoding" not in plain.to_dict()
    path.write_text('encoding = "srgb"\n' + camera)
    scene = load_scene(path)
    assert scene.encoding == "srgb"
    assert Scene.from_dict(scene.to_dict()).encoding == "srgb"
    path.write_text('encoding = "gamma"\n' + camera)
    with pytest.raises(ValueError, match="encoding"):
        load_scene(path)
