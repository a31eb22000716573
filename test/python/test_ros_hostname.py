"""The ROS_HOSTNAME environment hook (scripts/env-hooks/50.dslam_ros_hostname.sh): sets
ROS_HOSTNAME=localhost only when neither ROS_HOSTNAME nor ROS_IP is set and the host name does
not resolve; and `source devel/setup.bash` of the built workspace runs it."""
import os
import stat
import subprocess
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
HOOK = os.path.join(HERE, "..", "..", "scripts", "env-hooks", "50.dslam_ros_hostname.sh")


def fake_hostname(folder, name):
    """An executable in `folder` that prints `name` (stands in for `hostname`)."""
    path = os.path.join(folder, "fake_hostname")
    with open(path, "w") as f:
        f.write("#!/bin/sh\necho '%s'\n" % name)
    os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
    return path


def hostname_after(script, host, **env):
    """ROS_HOSTNAME (or '<unset>') after `script` ran in sh with `host` as the host name, and
    what it wrote to stderr."""
    with tempfile.TemporaryDirectory() as folder:
        clean = {k: v for k, v in os.environ.items() if k not in ("ROS_HOSTNAME", "ROS_IP")}
        clean.update(env, DSLAM_HOSTNAME_CHECK=fake_hostname(folder, host))
        out = subprocess.run(["bash", "-c", '. "$0"; echo "${ROS_HOSTNAME:-<unset>}"', script],
                             env=clean, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, check=True)
        return out.stdout.strip(), out.stderr


def find_devel_setup():
    """devel/setup.bash of the workspace whose libraries are on LD_LIBRARY_PATH (as catkin runs
    the tests), or build/ws beside the repository."""
    candidates = [os.path.join(p, "..", "setup.bash")
                  for p in os.environ.get("LD_LIBRARY_PATH", "").split(":") if p]
    candidates.append(os.path.join(HERE, "..", "..", "build", "ws", "devel", "setup.bash"))
    for path in candidates:
        if os.path.exists(path) and os.path.exists(os.path.join(os.path.dirname(path), "lib",
                                                                "libdslam_ros.so")):
            return os.path.realpath(path)
    return None


class RosHostnameHook(unittest.TestCase):
    def test_unresolvable_host_name_gets_localhost(self):
        value, said = hostname_after(HOOK, "no-such-host.invalid")
        self.assertEqual(value, "localhost")
        self.assertIn("no-such-host.invalid", said)

    def test_resolvable_host_name_is_left_alone(self):
        self.assertEqual(hostname_after(HOOK, "localhost"), ("<unset>", ""))

    def test_a_set_variable_is_never_overridden(self):
        self.assertEqual(hostname_after(HOOK, "no-such-host.invalid", ROS_HOSTNAME="robot")[0],
                         "robot")
        self.assertEqual(hostname_after(HOOK, "no-such-host.invalid", ROS_IP="10.0.0.2")[0],
                         "<unset>")

    def test_empty_host_name_gets_localhost(self):
        self.assertEqual(hostname_after(HOOK, "")[0], "localhost")

    def test_the_workspace_setup_runs_the_hook(self):
        setup = find_devel_setup()
        if setup is None:
            self.skipTest("no built workspace")
        self.assertEqual(hostname_after(setup, "no-such-host.invalid")[0], "localhost")


if __name__ == "__main__":
    unittest.main()
