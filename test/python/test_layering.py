"""The layering of the built libraries: the nodelet library and every dslam library it loads
(readelf -d, transitively) contain no code of the scene generator (dslam_synth) or the metrics
(dslam_eval): no symbol defined in libdslam_synth.so or libdslam_eval.so is defined there too
(nm -DC --defined-only). The include rule is checked when CMake configures (cmake/dslam_parts.cmake).
"""
import os
import re
import subprocess
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))


def find_library_dir():
    """The folder holding libdslam_ros.so: the workspace's devel/lib (on LD_LIBRARY_PATH when run
    by catkin) or build/ws/devel/lib beside the repository."""
    candidates = os.environ.get("LD_LIBRARY_PATH", "").split(":")
    candidates.append(os.path.join(HERE, "..", "..", "build", "ws", "devel", "lib"))
    for folder in candidates:
        if folder and os.path.exists(os.path.join(folder, "libdslam_ros.so")):
            return os.path.realpath(folder)
    raise RuntimeError("libdslam_ros.so not found (build the workspace first)")


def needed_dslam_libraries(path):
    """Names of the libdslam_* libraries that `path` lists as NEEDED."""
    out = subprocess.run(["readelf", "-d", path], check=True, stdout=subprocess.PIPE,
                         text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[(libdslam_\w+\.so)\]", out)


def closure(folder, name):
    """`name` and every libdslam_* library it loads, transitively."""
    seen, todo = set(), [name]
    while todo:
        lib = todo.pop()
        if lib in seen:
            continue
        seen.add(lib)
        todo.extend(needed_dslam_libraries(os.path.join(folder, lib)))
    return seen


def defined_symbols(path):
    """Demangled names of the functions `path` defines as strong global symbols (nm -DC
    --defined-only, type T): inline functions and template instances (type W) may be emitted in
    every library that uses them, a strong definition only where its source file is compiled."""
    out = subprocess.run(["nm", "-DC", "--defined-only", path], check=True,
                         stdout=subprocess.PIPE, text=True).stdout
    symbols = set()
    for line in out.splitlines():
        parts = line.split(" ", 2)
        if len(parts) == 3 and parts[1] == "T":
            symbols.add(parts[2])
    return symbols


class NodeletLayeringTest(unittest.TestCase):
    def setUp(self):
        self.folder = find_library_dir()
        self.nodelet = closure(self.folder, "libdslam_ros.so")

    def test_nodelet_loads_neither_generator_nor_metrics(self):
        self.assertIn("libdslam_tracking.so", self.nodelet)
        self.assertNotIn("libdslam_synth.so", self.nodelet)
        self.assertNotIn("libdslam_eval.so", self.nodelet)

    def test_no_generator_or_metrics_code_in_nodelet_libraries(self):
        forbidden = set()
        for lib in ("libdslam_synth.so", "libdslam_eval.so"):
            own = defined_symbols(os.path.join(self.folder, lib))
            self.assertTrue(own, lib + " defines no code")
            forbidden |= own
        for lib in sorted(self.nodelet):
            shared = defined_symbols(os.path.join(self.folder, lib)) & forbidden
            self.assertFalse(shared, "%s holds code of the generator or metrics: %s"
                             % (lib, sorted(shared)[:5]))


if __name__ == "__main__":
    unittest.main()
