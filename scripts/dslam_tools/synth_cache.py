"""Whether a folder dslam_synth rendered into a benchmark's cache can be used again."""
import os


def is_current(folder, scenario, files=("groundtruth.txt",)):
    """True when `folder` holds `files` and a camera.yaml as dslam_synth writes it today: one of a
    Gaussian-noise scene states its depth noise (depth_sigma_d_quadratic), which folders rendered
    before 2026-12-05 lack (dslam_run_dataset would model them as a real camera); a
    structured-light scene (`*_kinect`) states none."""
    if not all(os.path.exists(os.path.join(folder, name)) for name in files):
        return False
    if scenario.endswith("_kinect"):
        return True
    try:
        with open(os.path.join(folder, "camera.yaml")) as camera:
            return "depth_sigma_d_quadratic:" in camera.read()
    except OSError:
        return False
