#!/usr/bin/env python3
"""Long-run test of the dslam odometry node: the periodic synthetic scenario `loop` (rendered once
into OUT/loop_s<seed>) is published by dslam_replay at 30 Hz with ever-increasing stamps into
dslam_odometry_node (back end on, exact synchronisation) for --minutes minutes, on a roscore of
its own (a free port); minute 1 starts when the first status message arrives.

Every minute it prints a row: VmRSS and VmHWM of the node (/proc/PID/status), the node's frame
counters (received / processed / dropped, from /dslam/status), median and p95 of tracking_ms and
total_ms over the frames of that minute, tracking states, map points and keyframe window. At the
end it checks:
  1. memory: VmRSS and VmHWM at the last minute exceed those at minute 3 by less than 3 %;
  2. frame time: the last minute's median tracking_ms is within 5 % of minute 3's;
  3. no frame lost: frames_dropped = frames_rejected = 0 and frames_received = frames published;
  4. save_refined_trajectory, called once a minute, holds the map lock at most 5 ms (its reply says
     how long).
Exit status 0 when all hold, 1 otherwise, 2 when the run itself failed.

  scripts/long_run.py [--minutes 10] [--seed 1] [--rate 30] [--out build/long_run]
                      [--param KEY=VALUE ...] [--subscribe TOPIC ...]
                      [--node-wrapper 'heaptrack -o FILE']
Needs the built workspace (DSLAM_WS or build/ws; targets dslam_ros, dslam_odometry_node_main,
dslam_replay_main, dslam_synth_main, dslam_generate_messages_py).
"""

import argparse
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from dslam_tools.stats import NAN, median, quantile  # noqa: E402

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WS = os.environ.get("DSLAM_WS", os.path.join(REPO, "build", "ws"))
BIN = os.path.join(WS, "devel", "lib", "dslam")
STATES = ["initialised", "tracking", "recovered", "lost"]
MEMORY_GROWTH_LIMIT = 0.03
FRAME_TIME_LIMIT = 0.05
SAVE_LOCK_LIMIT_MS = 5.0  # save_refined_trajectory, called once a minute
REFERENCE_MINUTE = 3  # the map reaches its cap within it; later minutes are judged against it


def ros_environment():
    """This process's environment with the workspace's devel/setup.bash sourced (Debian's
    python3 first on PATH, as scripts/setup.sh)."""
    setup = os.path.join(WS, "devel", "setup.bash")
    if not os.path.exists(setup):
        sys.exit("long_run: %s not found (build the workspace: scripts/setup.sh)" % setup)
    env = dict(os.environ, PATH="/usr/bin:/bin:/usr/sbin:/sbin:" + os.environ.get("PATH", ""))
    out = subprocess.run(["bash", "-c", "source '%s' && env -0" % setup], env=env, check=True,
                         stdout=subprocess.PIPE).stdout
    return dict(item.split("=", 1) for item in out.decode().split("\0") if "=" in item)


def free_port():
    with socket.socket() as s:
        s.bind(("localhost", 0))
        return s.getsockname()[1]


def cpu_seconds(pid):
    """User + system CPU time of process `pid` [s] (/proc/PID/stat, its threads included)."""
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def proc_memory_mb(pid):
    """(VmRSS, VmHWM) of process `pid` [MB] from /proc/PID/status."""
    fields = {}
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            key, _, value = line.partition(":")
            if key in ("VmRSS", "VmHWM"):
                fields[key] = int(value.split()[0]) / 1024.0  # kB -> MB
    return fields["VmRSS"], fields["VmHWM"]


class StatusMonitor:
    """Collects /dslam/status per minute: frame times, states, and the newest message."""

    def __init__(self):
        self.lock = threading.Lock()
        self.first_wall = None
        self.last = None
        self.bucket = self.new_bucket()

    @staticmethod
    def new_bucket():
        return {"tracking_ms": [], "total_ms": [], "latency_ms": [], "lock_ms": 0.0, "keyframes": 0,
                "backend_runs": 0, "max_backlog": 0, "window": 0,
                "states": dict.fromkeys(STATES, 0)}

    def __call__(self, msg):
        with self.lock:
            if self.first_wall is None:
                self.first_wall = time.time()
            self.last = msg
            b = self.bucket
            b["tracking_ms"].append(msg.tracking_ms)
            b["total_ms"].append(msg.total_ms)
            b["latency_ms"].append(msg.latency_ms)
            b["lock_ms"] = max(b["lock_ms"], msg.map_lock_max_ms)
            b["keyframes"] += int(msg.keyframe)
            b["backend_runs"] += int(msg.backend_delivered or msg.backend_ran)
            b["max_backlog"] = max(b["max_backlog"], msg.backend_backlog)
            b["window"] = max(b["window"], msg.window_keyframes)
            b["states"][msg.state] = b["states"].get(msg.state, 0) + 1

    def take(self):
        """The current minute's bucket and the newest message; starts a new bucket."""
        with self.lock:
            bucket, self.bucket = self.bucket, self.new_bucket()
            return bucket, self.last


HEADER = ("| min | VmRSS MB | VmHWM MB | received | processed | dropped | frames | tracking ms "
          "med / p95 | total ms med / p95 | latency ms med | states t / r / l / i | keyframes | "
          "BA runs | loops | map points | window max | longest map-lock hold ms | "
          "CPU node / replay % | load |")
SEPARATOR = "|" + "---|" * (HEADER.count("|") - 1)


def row(minute, rss, hwm, bucket, last, cpu):
    s = bucket["states"]
    times_ms = [quantile(bucket[key], fraction, NAN) for key, fraction in [
        ("tracking_ms", 0.5), ("tracking_ms", 0.95), ("total_ms", 0.5), ("total_ms", 0.95),
        ("latency_ms", 0.5)]]
    return ("| %d | %.1f | %.1f | %d | %d | %d | %d | %.1f / %.1f | %.1f / %.1f | %.1f | "
            "%d / %d / %d / %d | %d | %d | %d | %d | %d | %.1f | %.0f / %.0f | %.1f |" % (
                minute, rss, hwm, last.frames_received, last.frames_processed,
                last.frames_dropped, len(bucket["tracking_ms"]),
                *times_ms, s["tracking"], s["recovered"], s["lost"],
                s["initialised"], bucket["keyframes"], bucket["backend_runs"], last.loop_closures, last.map_points,
                bucket["window"], bucket["lock_ms"], cpu[0], cpu[1], os.getloadavg()[0]))


class Processes:
    """The processes this script started, each in its own process group; stopped in reverse."""

    def __init__(self, env, log_dir):
        self.env, self.log_dir, self.started = env, log_dir, []

    def start(self, name, cmd):
        log = open(os.path.join(self.log_dir, name + ".log"), "w")
        proc = subprocess.Popen(cmd, env=self.env, stdout=log, stderr=subprocess.STDOUT,
                                start_new_session=True)
        self.started.append((name, proc, log))
        return proc

    def stop_all(self):
        for name, proc, log in reversed(self.started):
            if proc.poll() is None:
                os.killpg(proc.pid, signal.SIGINT)
                try:
                    proc.wait(timeout=15)
                except subprocess.TimeoutExpired:
                    os.killpg(proc.pid, signal.SIGKILL)
                    proc.wait()
            log.close()


def render(env, out, seed):
    """The `loop` scenario's folder, rendered once (reused when complete)."""
    folder = os.path.join(out, "loop_s%d" % seed)
    if not os.path.isdir(folder):
        partial = folder + ".partial"  # renamed when complete: an interrupted render is redone
        print("long_run: rendering the loop scenario (seed %d) into %s" % (seed, folder),
              flush=True)
        subprocess.run(["rm", "-rf", partial], check=True)
        subprocess.run([os.path.join(BIN, "dslam_synth"), "--scenario", "loop", "--seed",
                        str(seed), "--output", partial], env=env, check=True,
                       stdout=subprocess.DEVNULL)
        os.rename(partial, folder)
    return folder


def start_ros(procs, env, params, wrapper):
    """roscore on the environment's ROS_MASTER_URI port, the node's parameters, the node."""
    import rosgraph  # the workspace's environment is active (main re-executes this script)
    port = int(env["ROS_MASTER_URI"].rsplit(":", 1)[1])
    procs.start("roscore", ["roscore", "-p", str(port)])
    deadline = time.time() + 60
    while not rosgraph.is_master_online(env["ROS_MASTER_URI"]):
        if time.time() > deadline:
            raise RuntimeError("roscore did not come up on port %d" % port)
        time.sleep(0.2)
    for yaml in ["config/default.yaml", "config/ros/node.yaml"]:
        subprocess.run(["rosparam", "load", os.path.join(REPO, yaml), "/dslam/odometry"],
                       env=env, check=True)
    for key, value in params:
        subprocess.run(["rosparam", "set", "/dslam/odometry/" + key, value], env=env, check=True)
    return procs.start("node", wrapper + [
        os.path.join(BIN, "dslam_odometry_node"), "__ns:=/dslam", "__name:=odometry",
        "rgb/image:=/camera/rgb/image", "depth/image:=/camera/depth/image",
        "rgb/camera_info:=/camera/rgb/camera_info"])


def find_node_pid(wrapper, timeout_s=30.0):
    """The dslam_odometry_node process started by `wrapper` (a Popen: heaptrack, valgrind, ...):
    the descendant whose command name is the node's."""
    deadline = time.time() + timeout_s
    while time.time() < deadline:
        parents = {}
        for entry in filter(str.isdigit, os.listdir("/proc")):
            try:
                with open("/proc/%s/stat" % entry) as f:
                    name_and_rest = f.read()
            except (OSError, ValueError):
                continue
            name = name_and_rest[name_and_rest.find("(") + 1:name_and_rest.rfind(")")]
            ppid = int(name_and_rest.rsplit(")", 1)[1].split()[1])
            parents[int(entry)] = (ppid, name)
        for pid, (_, name) in parents.items():
            ancestor = pid
            while ancestor in parents and ancestor != wrapper.pid:
                ancestor = parents[ancestor][0]
            if ancestor == wrapper.pid and name.startswith("dslam_odometry"):
                return pid
        time.sleep(0.2)
    raise RuntimeError("no dslam_odometry_node below the wrapper process %d" % wrapper.pid)


def replay_count(log_path):
    """Frames dslam_replay reports as published (its last line), or None."""
    with open(log_path) as f:
        found = re.findall(r"published (\d+) frames", f.read())
    return int(found[-1]) if found else None


def monitor(args, node, node_pid, replay, status):
    """Prints a row per minute of the replay; returns the rows' data."""
    deadline = time.time() + 120
    while status.first_wall is None:
        for name, proc in [("node", node), ("replay", replay)]:
            if proc.poll() is not None:
                raise RuntimeError("%s exited (see %s/%s.log)" % (name, args.log_dir, name))
        if time.time() > deadline:
            raise RuntimeError("no status from the node (see the logs in %s)" % args.log_dir)
        time.sleep(0.1)
    print(HEADER + "\n" + SEPARATOR, flush=True)
    rows = []
    cpu_before = [cpu_seconds(node_pid), cpu_seconds(replay.pid)]
    for minute in range(1, args.minutes + 1):
        time.sleep(max(0.0, status.first_wall + 60.0 * minute - time.time()))
        if node.poll() is not None:
            raise RuntimeError("the node exited (see %s/node.log)" % args.log_dir)
        rss, hwm = proc_memory_mb(node_pid)
        bucket, last = status.take()
        cpu_now = [cpu_seconds(node_pid), cpu_seconds(replay.pid) if replay.poll() is None
                   else cpu_before[1]]
        cpu = [100.0 * (now - before) / 60.0 for now, before in zip(cpu_now, cpu_before)]
        cpu_before = cpu_now
        rows.append({"rss": rss, "hwm": hwm, "bucket": bucket, "last": last,
                     "save_lock_ms": save_refined_lock_ms(args)})
        print(row(minute, rss, hwm, bucket, last, cpu), flush=True)
    print("save_refined_trajectory, map lock held per minute [ms]: " +
          " ".join("%.3f" % r["save_lock_ms"] for r in rows), flush=True)
    return rows


def save_refined_lock_ms(args):
    """Calls save_refined_trajectory (into the log folder) and returns how long it held the map
    lock [ms], from its message; NaN when the call failed."""
    import rospy
    from dslam.srv import SaveTrajectory
    try:
        result = rospy.ServiceProxy("/dslam/save_refined_trajectory", SaveTrajectory)(
            os.path.join(args.log_dir, "refined.txt"))
    except rospy.ServiceException:
        return NAN
    found = re.search(r"map lock held ([0-9.]+) ms", result.message)
    return float(found.group(1)) if result.success and found else NAN


def check(rows, final, published):
    """The three checks; returns a list of (ok, text)."""
    results = []
    ref = REFERENCE_MINUTE - 1
    if len(rows) <= ref + 1:
        results.append((False, "the checks need --minutes > %d" % REFERENCE_MINUTE))
        return results
    for key, name in [("rss", "VmRSS"), ("hwm", "VmHWM")]:
        growth = rows[-1][key] / rows[ref][key] - 1.0
        text = "%s growth after minute %d: %.1f -> %.1f MB (%+.1f %%, limit %.0f %%)" % (
            name, REFERENCE_MINUTE, rows[ref][key], rows[-1][key], 100 * growth,
            100 * MEMORY_GROWTH_LIMIT)
        results.append((growth < MEMORY_GROWTH_LIMIT, text))
    first = median(rows[ref]["bucket"]["tracking_ms"], NAN)
    last = median(rows[-1]["bucket"]["tracking_ms"], NAN)
    change = last / first - 1.0
    results.append((abs(change) <= FRAME_TIME_LIMIT,
                    "median tracking_ms, last minute against minute %d: %.2f -> %.2f ms (%+.1f %%, "
                    "limit +-%.0f %%)" % (REFERENCE_MINUTE, first, last, 100 * change,
                                          100 * FRAME_TIME_LIMIT)))
    worst = max(r["save_lock_ms"] for r in rows)
    results.append((worst <= SAVE_LOCK_LIMIT_MS,
                    "save_refined_trajectory held the map lock %.3f ms at most (limit %.0f ms)" % (
                        worst, SAVE_LOCK_LIMIT_MS)))
    lost = final.frames_dropped + final.frames_rejected
    results.append((lost == 0 and published is not None and final.frames_received == published,
                    "frames: published %s, received %d, processed %d, dropped %d, rejected %d" % (
                        published, final.frames_received, final.frames_processed,
                        final.frames_dropped, final.frames_rejected)))
    return results


def run(args, env):
    folder = render(env, args.out, args.seed)
    procs = Processes(env, args.log_dir)
    try:
        node = start_ros(procs, env, args.param, args.node_wrapper.split())
        node_pid = find_node_pid(node) if args.node_wrapper else node.pid
        import rospy
        from dslam.msg import FrameStatus
        rospy.init_node("long_run_monitor", disable_signals=True)
        status = StatusMonitor()
        rospy.Subscriber("/dslam/status", FrameStatus, status, queue_size=1000,
                         tcp_nodelay=True)
        received = {topic: 0 for topic in args.subscribe}
        for topic in args.subscribe:  # held for the whole run, as a planner or rviz would
            rospy.Subscriber(topic, rospy.AnyMsg, lambda _, t=topic: received.update(
                {t: received[t] + 1}), queue_size=1)
        replay = procs.start("replay", [
            os.path.join(BIN, "dslam_replay"), "--dataset", folder, "--rate", str(args.rate),
            "--duration", str(60.0 * args.minutes), "--wait-subscribers", "60", "__ns:=/camera"])
        rows = monitor(args, node, node_pid, replay, status)
        replay.wait(timeout=120)
        time.sleep(3.0)  # the node finishes the last frame
        final = status.last
        published = replay_count(os.path.join(args.log_dir, "replay.log"))
        node_rss, node_hwm = proc_memory_mb(node_pid)
    finally:
        procs.stop_all()
    results = check(rows, final, published)
    for topic, count in sorted(received.items()):
        print("received %d messages on %s" % (count, topic))
    print("\nnode at the end: VmRSS %.1f MB, VmHWM %.1f MB; logs in %s" % (node_rss, node_hwm,
                                                                          args.log_dir))
    for ok, text in results:
        print("%s  %s" % ("PASS" if ok else "FAIL", text))
    passed = all(ok for ok, _ in results)
    print("long_run: %s" % ("all checks passed" if passed else "FAILED"))
    return 0 if passed else 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=int, default=10, help="replay duration [min]")
    parser.add_argument("--seed", type=int, default=1, help="seed of the loop scenario")
    parser.add_argument("--rate", type=float, default=30.0, help="replay rate [Hz]")
    parser.add_argument("--out", default=os.path.join(REPO, "build", "long_run"),
                        help="rendered scenario and logs")
    parser.add_argument("--param", action="append", default=[], metavar="KEY=VALUE",
                        help="node parameter (below ~), after config/default.yaml and "
                             "config/ros/node.yaml; backend/enabled=true and exact_sync=true "
                             "are set first")
    parser.add_argument("--subscribe", action="append", default=[], metavar="TOPIC",
                        help="holds a subscriber on TOPIC for the whole run (e.g. /dslam/grid: "
                             "the node then rebuilds the grid and logs its times once a minute)")
    parser.add_argument("--node-wrapper", default="", metavar="COMMAND",
                        help="runs the node under COMMAND, e.g. 'heaptrack -o FILE' (memory and "
                             "CPU are then those of the node process below it)")
    args = parser.parse_args()
    # Exact synchronisation: the replay's three messages of a frame carry the same stamp, and the
    # approximate policy holds the newest set back until a later message arrives (the last frame
    # would never be received).
    args.param = [("backend/enabled", "true"), ("exact_sync", "true")] + [
        tuple(p.split("=", 1)) for p in args.param]
    if args.minutes < 1 or args.rate <= 0:
        parser.error("--minutes must be >= 1 and --rate > 0")
    args.out = os.path.abspath(args.out)
    if os.environ.get("DSLAM_LONG_RUN_ENV") != "1":  # re-run inside the workspace's environment
        env = ros_environment()
        env.update(DSLAM_LONG_RUN_ENV="1", ROSCONSOLE_STDOUT_LINE_BUFFERED="1",
                   ROS_MASTER_URI="http://localhost:%d" % free_port(),
                   ROS_HOME=os.path.join(args.out, "ros_home"))
        os.execve("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv, env)
    args.log_dir = os.path.join(args.out, "logs", time.strftime("%Y%m%d-%H%M%S"))
    os.makedirs(args.log_dir, exist_ok=True)
    try:
        return run(args, dict(os.environ))
    except (RuntimeError, subprocess.SubprocessError, OSError) as e:
        print("long_run: run failed: %s" % e, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
