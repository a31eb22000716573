"""The node's malloc is jemalloc: dslam_odometry_node lists libjemalloc.so.2 as NEEDED before
libc.so.6 (so its malloc serves the whole process) and exports `malloc_conf` (jemalloc's options,
background_thread on), and dslam.launch starts its nodelet manager with libjemalloc.so.2 preloaded,
a library the dynamic loader finds (ldconfig's cache), and the same option in MALLOC_CONF.
test_heap_report_jemalloc shows the mechanism: a binary linked this way allocates from jemalloc."""
import os
import re
import subprocess
import sys
import unittest
import xml.etree.ElementTree as ElementTree

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)  # nose does not add it
from test_layering import find_library_dir  # noqa: E402
LAUNCH = os.path.join(HERE, "..", "..", "launch", "dslam.launch")


def needed(path):
    """The NEEDED shared libraries of `path`, in the order the dynamic loader searches them."""
    out = subprocess.run(["readelf", "-d", path], check=True, stdout=subprocess.PIPE,
                         text=True).stdout
    return re.findall(r"\(NEEDED\)\s+Shared library: \[([^\]]+)\]", out)


class NodeAllocatorTest(unittest.TestCase):
    def test_node_links_jemalloc_before_libc(self):
        node = os.path.join(find_library_dir(), "dslam", "dslam_odometry_node")
        libraries = needed(node)
        self.assertIn("libjemalloc.so.2", libraries)
        self.assertIn("libc.so.6", libraries)
        self.assertLess(libraries.index("libjemalloc.so.2"), libraries.index("libc.so.6"))

    def test_node_exports_jemallocs_options(self):
        node = os.path.join(find_library_dir(), "dslam", "dslam_odometry_node")
        out = subprocess.run(["nm", "-D", "--defined-only", node], check=True,
                             stdout=subprocess.PIPE, text=True).stdout
        self.assertRegex(out, r"\s[DR] malloc_conf\n")

    def test_launch_preloads_jemalloc_into_the_manager(self):
        root = ElementTree.parse(LAUNCH).getroot()
        default = {a.get("name"): a.get("default") for a in root.iter("arg")}
        managers = [n for n in root.iter("node") if n.get("args") == "manager"]
        self.assertEqual(len(managers), 1)
        prefix = managers[0].get("launch-prefix").replace(
            "$(arg manager_preload)", default["manager_preload"])
        self.assertEqual(prefix, "env LD_PRELOAD=libjemalloc.so.2 MALLOC_CONF=background_thread:true")
        cache = subprocess.run(["/sbin/ldconfig", "-p"], check=True, stdout=subprocess.PIPE,
                               text=True).stdout
        self.assertIn("libjemalloc.so.2 ", cache)


if __name__ == "__main__":
    unittest.main()
