"""Helpers for the tests that drive the real programs: the command-line tool and meshlabserver."""
import hashlib
import os
import shutil
import subprocess
import tempfile
import unittest

BUILD = os.environ["CI_BUILD_DIR"]
SOURCE = os.environ["CI_SOURCE_DIR"]
SHARED_MESHES = os.path.join(SOURCE, "..", "shared", "meshes")
TOOL = os.path.join(BUILD, "bin", "curvature-inpaint")
PLUGIN = os.path.join(BUILD, "plugins", "libfilter_curvature_inpaint.so")
SCRIPTS = os.path.join(SOURCE, "filter_curvature_inpaint", "scripts")
MESHLAB_LIB = "/usr/lib/x86_64-linux-gnu/meshlab"


def run(args, timeout=300):
    return subprocess.run(args, capture_output=True, text=True, timeout=timeout)


def sha256(path):
    with open(path, "rb") as f:
        return hashlib.sha256(f.read()).hexdigest()


def info(path, *options):
    """The tool's `info` report as a dict of ints (hole_edges as a list), and under "numbered"
    the boundary edges of the holes fill would fill, by their numbers."""
    r = run([TOOL, "info", path, *options])
    if r.returncode != 0:
        raise AssertionError(f"info {path} failed: {r.stderr}")
    out = {"numbered": {}}
    for line in r.stdout.splitlines():
        key, *values = line.split()
        if key == "hole":  # hole K: E edges, diameter ..., centre ...
            out["numbered"][int(values[0].rstrip(":"))] = int(values[1])
        elif key != "left":  # left open: ...
            out[key] = [int(v) for v in values] if key == "hole_edges" else int(values[0])
    return out


def write_ascii_ply(path, vertices, faces):
    with open(path, "w") as f:
        f.write("ply\nformat ascii 1.0\n")
        f.write(f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n")
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n")
        for v in vertices:
            f.write(" ".join(str(c) for c in v) + "\n")
        for t in faces:
            f.write("3 " + " ".join(str(i) for i in t) + "\n")


def write_binary_ply(path, vertices, faces):
    import struct
    with open(path, "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\n")
        f.write(f"element vertex {len(vertices)}\nproperty float x\nproperty float y\nproperty float z\n".encode())
        f.write(f"element face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n".encode())
        f.write(b"".join(struct.pack("<3f", *v) for v in vertices))
        f.write(b"".join(struct.pack("<B3i", 3, *t) for t in faces))


def grid(n):
    """A flat (n+1)^2 grid in z = 0 and its triangles."""
    vertices = [(j / n, i / n, 0.0) for i in range(n + 1) for j in range(n + 1)]
    faces = []
    for i in range(n):
        for j in range(n):
            a, b, c, d = i * (n + 1) + j, i * (n + 1) + j + 1, (i + 1) * (n + 1) + j, (i + 1) * (n + 1) + j + 1
            faces += [(a, b, d), (a, d, c)]
    return vertices, faces


def png_size(path):
    """(width, height) from a PNG's IHDR chunk; fails if the file is not a PNG."""
    with open(path, "rb") as f:
        head = f.read(24)
    if head[:8] != b"\x89PNG\r\n\x1a\n" or head[12:16] != b"IHDR":
        raise AssertionError(f"{path} is not a PNG")
    return int.from_bytes(head[16:20], "big"), int.from_bytes(head[20:24], "big")


def write_non_manifold_ply(path):
    """A small grid with a third face on one of its edges."""
    v, f = grid(4)
    v.append((0.3, 0.3, 1.0))
    f.append((6, 7, len(v) - 1))
    write_ascii_ply(path, v, f)
    return path


def make_meshlab_prefix(root):
    """A private MeshLab prefix whose meshlabserver loads the built plugin (no root needed)."""
    lib = os.path.join(root, "lib", "x86_64-linux-gnu", "meshlab")
    plugins = os.path.join(lib, "plugins")
    os.makedirs(plugins)
    os.makedirs(os.path.join(root, "bin"))
    for exe in ("meshlabserver", "meshlab"):
        shutil.copy(f"/usr/bin/{exe}", os.path.join(root, "bin", exe))
    for name in os.listdir(MESHLAB_LIB):
        if name.startswith("libmeshlab-common.so"):
            os.symlink(os.path.join(MESHLAB_LIB, name), os.path.join(lib, name))
    for name in os.listdir(os.path.join(MESHLAB_LIB, "plugins")):
        os.symlink(os.path.join(MESHLAB_LIB, "plugins", name), os.path.join(plugins, name))
    os.symlink(PLUGIN, os.path.join(plugins, os.path.basename(PLUGIN)))
    return os.path.join(root, "bin")


class TempDirTest(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="ci-test-")
        self.addCleanup(shutil.rmtree, self.tmp, ignore_errors=True)

    def path(self, name):
        return os.path.join(self.tmp, name)

    def punched_twice(self, mesh, first, second):
        """`mesh` with two holes, each (seed vertex, radius fraction); the second seed indexes
        the mesh after the first hole."""
        once = self.punched(mesh, *first, "once.ply")
        twice = self.path("twice.ply")
        r = run([TOOL, "punch", once, twice, "--seed-vertex", str(second[0]), "--radius-frac", str(second[1])])
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(info(twice)["holes"], 2)
        return twice

    def collection(self, count, vertex_step=1000, name="scans"):
        """A folder of `count` fandisks, scan<k>.ply, each with one hole at its own vertex."""
        folder = self.path(name)
        os.makedirs(folder, exist_ok=True)
        for i in range(count):
            r = run([TOOL, "punch", os.path.join(SHARED_MESHES, "fandisk.ply"),
                     os.path.join(folder, f"scan{i + 1}.ply"),
                     "--seed-vertex", str(vertex_step * (i + 1)), "--radius-frac", "0.03"])
            self.assertEqual(r.returncode, 0, r.stderr)
        return folder

    def punched(self, mesh, seed, radius_frac, name="punched.ply"):
        out = self.path(name)
        r = run([TOOL, "punch", os.path.join(SHARED_MESHES, mesh), out,
                 "--seed-vertex", str(seed), "--radius-frac", str(radius_frac)])
        self.assertEqual(r.returncode, 0, r.stderr)
        return out


def read_binary_ply_face_flags(path):
    """The `flags` of every face of a binary little-endian PLY whose faces are triangles with
    `list uchar int vertex_indices` then `int flags` (as the tool writes them)."""
    import struct
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    assert "binary_little_endian" in header and "property int flags" in header, header
    nv = int(header.split("element vertex ")[1].split()[0])
    nf = int(header.split("element face ")[1].split()[0])
    props = header.split("element vertex")[1].split("element face")[0]
    sizes = {"float": 4, "double": 8, "uchar": 1, "int": 4, "uint": 4}
    stride = sum(sizes[line.split()[1]] for line in props.splitlines() if line.startswith("property"))
    start = end + nv * stride
    flags = []
    for i in range(nf):
        at = start + i * 17
        assert data[at] == 3, "not a triangle"
        flags.append(struct.unpack_from("<i", data, at + 13)[0])
    return flags


def read_binary_ply_xyz(path):
    """Vertex coordinates of a binary little-endian PLY whose vertices start with float x y z."""
    import struct
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    assert "binary_little_endian" in header, header
    n = int(header.split("element vertex ")[1].split()[0])
    props = header.split("element vertex")[1].split("element face")[0]
    sizes = {"float": 4, "double": 8, "uchar": 1, "int": 4, "uint": 4}
    stride = sum(sizes[line.split()[1]] for line in props.splitlines() if line.startswith("property"))
    return [struct.unpack_from("<3f", data, end + i * stride) for i in range(n)]
