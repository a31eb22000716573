"""Synthetic scenes for the rostests, rendered once per test run: with DSLAM_TEST_SCENES set
(scripts/test.sh: a new folder per run) the first test that asks for a scene renders it there
with dslam_synth (under a file lock, so tests running at the same time wait for one render) and
later tests reuse it; without it, each call renders into a new temporary folder. The scenes are
read, never changed, by the tests."""
import fcntl
import os
import shutil
import subprocess
import tempfile


def scene(scenario, frames, with_bag=False):
    """(folder, bag) of `frames` frames of `scenario`, seed 1; bag is None without `with_bag`."""
    name = "%s_f%d_s1%s" % (scenario, frames, "_bag" if with_bag else "")
    root = os.environ.get("DSLAM_TEST_SCENES")
    if not root:
        return render(tempfile.mkdtemp(prefix="dslam_rostest_"), scenario, frames, with_bag)
    base = os.path.join(root, "rostest", name)
    os.makedirs(os.path.dirname(base), exist_ok=True)
    with open(base + ".lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not os.path.isdir(base):
            partial = base + ".partial"
            shutil.rmtree(partial, ignore_errors=True)
            render(partial, scenario, frames, with_bag)
            os.rename(partial, base)
    return paths(base, scenario, with_bag)


def paths(work, scenario, with_bag):
    return (os.path.join(work, scenario),
            os.path.join(work, scenario + ".bag") if with_bag else None)


def render(work, scenario, frames, with_bag):
    """Renders into the folder `work` (created); returns paths(work, ...)."""
    os.makedirs(work, exist_ok=True)
    folder, bag = paths(work, scenario, with_bag)
    command = ["rosrun", "dslam", "dslam_synth", "--scenario", scenario, "--frames", str(frames),
               "--seed", "1", "--output", folder]
    subprocess.check_call(command + (["--bag", bag] if with_bag else []),
                          stdout=subprocess.DEVNULL)
    return folder, bag
