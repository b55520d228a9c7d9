"""The README and docs/: every link lands, and every command in a fenced `sh` block runs on the
sample mesh (those too slow or that change the machine are listed below, each with why)."""
import os
import re
import shutil
import subprocess
import unittest

from support import BUILD, SOURCE, TempDirTest

PAGES = ["README.md"] + sorted(os.path.join("docs", n) for n in os.listdir(os.path.join(SOURCE, "docs"))
                               if n.endswith(".md"))

# Commands not run here, by how they start, and what covers them instead; a block whose first
# command is one of them is not run at all.
SKIPPED = {
    "bash scripts/run-tests.sh": "it is the test run itself",
    "python3 bench/": "benchmarks take from minutes to an hour; their figures are in docs/benchmark.md",
    "/usr/bin/python3 train/": "making pairs and training take most of an hour and python3-torch; "
                               "tests/learned_inpainter_test.cpp checks the network they made",
    "sbatch ": "needs a Slurm cluster; tests/slurm_test.py runs the script on a real one-node Slurm",
    "sudo cp ": "changes the machine's MeshLab; tests/plugin_test.py loads the plugin from a prefix",
    "P=$HOME/meshlab-ci": "starts the MeshLab GUI; tests/gui_test.py does, under Xvfb",
    "xvfb-run -a meshlabserver": "needs the plugin installed; tests/meshlabserver_test.py runs the scripts",
    "sudo apt ": "changes the machine's packages; tests/package_test.py installs and removes each package in "
                 "a Debian root of its release",
    "cmake --build build -j2 && ctest": "the developers' quick loop: the test run runs these tests itself",
    "bash scripts/package.sh": "the test run makes the packages; tests/package_test.py checks them",
}


def slug(heading):
    """GitHub's anchor for a heading."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def anchors(path):
    found, fenced = set(), False
    with open(path) as f:
        for line in f:
            if line.startswith("```"):
                fenced = not fenced
            m = re.match(r"^#+ (.*)", line)
            if m and not fenced:
                found.add(slug(m.group(1)))
            found.update(re.findall(r'<a id="([^"]+)">', line))
    return found


def blocks(page):
    """(line number, commands) for every `sh` block of the page: continuation lines joined,
    comments dropped; in a block written as a session (`$ ` prompts), only the prompted
    lines."""
    with open(os.path.join(SOURCE, page)) as f:
        lines = f.read().split("\n")
    found, block, start = [], None, 0
    for number, line in enumerate(lines, 1):
        if line.startswith("```"):
            if block is None and line.strip() == "```sh":
                block, start = [], number
            elif block is not None:
                session = any(l.startswith("$ ") for l in block)
                joined = []
                for l in block:
                    if session and not l.startswith("$ "):
                        continue
                    l = l[2:] if session else l
                    if joined and joined[-1].endswith("\\"):
                        joined[-1] = joined[-1][:-1] + " " + l.strip()
                    else:
                        joined.append(l)
                found.append((start, [c for c in (re.sub(r"\s+#.*$", "", c).strip() for c in joined)
                                      if c]))
                block = None
            continue
        if block is not None:
            block.append(line)
    return found


class Docs(TempDirTest):
    def test_the_readme_is_short(self):
        with open(os.path.join(SOURCE, "README.md")) as f:
            self.assertLessEqual(len(f.read().splitlines()), 250)

    def test_every_link_lands(self):
        for page in PAGES:
            with open(os.path.join(SOURCE, page)) as f:
                text = f.read()
            for target in re.findall(r"\]\(([^)\s]+)\)", text):
                if re.match(r"^[a-z]+:", target):
                    continue
                with self.subTest(page=page, target=target):
                    path, _, anchor = target.partition("#")
                    dest = os.path.normpath(os.path.join(SOURCE, os.path.dirname(page), path)) \
                        if path else os.path.join(SOURCE, page)
                    self.assertTrue(os.path.exists(dest), dest)
                    if anchor:
                        self.assertIn(anchor, anchors(dest))

    def test_every_command_runs_on_the_sample(self):
        # A folder like the checkout, with the sample as scan.ply, where `curvature-inpaint` is
        # the built tool.
        for name in ("meshes", "scripts", "filter_curvature_inpaint", "build"):
            os.symlink(BUILD if name == "build" else os.path.join(SOURCE, name), self.path(name))
        shutil.copy(os.path.join(SOURCE, "meshes", "sample_holes.ply"), self.path("scan.ply"))
        os.makedirs(self.path("bin"))
        os.symlink(os.path.join(BUILD, "bin", "curvature-inpaint"), self.path("bin/curvature-inpaint"))
        env = dict(os.environ, PATH=self.path("bin") + os.pathsep + os.environ["PATH"])
        ran = 0
        for page in PAGES:
            for line, block in blocks(page):
                if any(block[0].startswith(s) for s in SKIPPED):
                    continue  # the block's later commands need what its first makes
                for command in block:
                    if any(command.startswith(s) for s in SKIPPED):
                        continue
                    # The main command builds in the checkout itself: run it there.
                    where = SOURCE if command.startswith("bash scripts/") else self.tmp
                    with self.subTest(page=page, line=line, command=command):
                        r = subprocess.run(["bash", "-c", command], cwd=where, env=env,
                                           capture_output=True, text=True, timeout=300)
                        self.assertEqual(r.returncode, 0, r.stderr[-2000:])
                        ran += 1
        self.assertGreaterEqual(ran, 8)


if __name__ == "__main__":
    unittest.main()
