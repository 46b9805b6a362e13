"""Running `hvi run` for the study: one run folder per run, reuse of completed runs, references."""
import json
import os
import shutil
import subprocess
import threading

import numpy as np

import study_exact as ex
import study_measure as ms


def _args_record(hvi, run, threads):
    # The binary's size and time stamp: a rebuilt hvi invalidates reused runs.
    st = os.stat(hvi)
    return {"scene": run["scene"], "sets": run["sets"], "threads": threads,
            "hvi": [st.st_size, int(st.st_mtime)]}


def run_hvi(hvi, run, threads, reuse, timeout=3600):
    """Runs one scene with its overrides; returns summary.json (plus `_load_before`), or a
    stand-in {status: failed, error: ...} when hvi wrote none."""
    d = run["dir"]
    rec_path = os.path.join(d, "study_args.json")
    summ_path = os.path.join(d, "summary.json")
    record = _args_record(hvi, run, threads)
    if reuse and os.path.exists(summ_path) and os.path.exists(rec_path):
        with open(rec_path) as f, open(summ_path) as g:
            old, summ = json.load(f), json.load(g)
        old_args = {k: old.get(k) for k in record}
        if old_args == record and summ.get("status") == "completed":
            summ["_load_before"] = old.get("load_before")
            summ["_cpu_seconds"] = old.get("cpu_seconds")
            return summ
    if os.path.isdir(d):
        shutil.rmtree(d)  # a run folder of this study: stale snapshots would be read otherwise
    os.makedirs(d)
    load = os.getloadavg()[0]
    cmd = [hvi, "run", run["scene"], "--out", d, "--quiet"]
    for s in run["sets"]:
        cmd += ["--set", s]
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    rc, err, cpu = _spawn(cmd, env, os.path.join(d, "stderr.txt"), timeout)
    summ = {}
    if os.path.exists(summ_path):
        with open(summ_path) as f:
            summ = json.load(f)
    if rc != 0 or summ.get("status") != "completed":
        summ.setdefault("status", "failed")
        summ["error"] = summ.get("error") or (err or "").strip()[-400:]
        summ["exit_code"] = rc
    record["load_before"] = load
    record["cpu_seconds"] = cpu
    with open(rec_path, "w") as f:
        json.dump(record, f, indent=1)
    summ["_load_before"] = load
    summ["_cpu_seconds"] = cpu
    return summ


def _spawn(cmd, env, log, timeout):
    """Runs `cmd` with stderr to `log`; returns (exit code, stderr text, CPU seconds of the
    child: user + system, from wait4, so parallel runs do not mix their accounts)."""
    with open(log, "w") as f:
        f.write(" ".join(f"'{c}'" if " " in c else c for c in cmd) + "\n")
        f.flush()
        p = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=f, env=env)
        timer = threading.Timer(timeout, p.kill)
        timer.start()
        try:
            _, status, usage = os.wait4(p.pid, 0)
        finally:
            timer.cancel()
        p.returncode = os.waitstatus_to_exitcode(status)
    with open(log) as f:
        err = f.read()
    return p.returncode, err, usage.ru_utime + usage.ru_stime


def reference_profile(problem, hvi, out):
    """exact(x, t) for a 1-D problem: python closed form, or the riemann solver on a fine grid."""
    if problem["kind"] != "exact":
        return None
    how, arg = problem["exact"]
    if how == "python":
        return arg
    run = {"dir": os.path.join(out, "reference-riemann"), "scene": problem["scene"],
           "sets": ["solver=riemann", f"riemann.cells={arg}", "output.vtk=false",
                    f'output.times=["{problem["end"]:g} us"]']}
    summ = run_hvi(hvi, run, 1, reuse=True)
    if summ.get("status") != "completed":
        print(f"study: the riemann reference failed: {summ.get('error')}")
        return None
    return ms.profile_from_grid(ms.snapshot_at(run["dir"], problem["end"]))


def riemann_crosscheck(hvi, out):
    """The C++ general-EOS Riemann solver (hvi, solver = riemann) against Toro's closed form."""
    scene = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))),
                         "cases", "scenes", "sod_x.toml")
    run = {"dir": os.path.join(out, "sod-riemann"), "scene": scene,
           "sets": ["solver=riemann", "riemann.cells=2000", "output.vtk=false"]}
    summ = run_hvi(hvi, run, 1, reuse=False)
    if summ.get("status") != "completed":
        print(f"  hvi riemann run failed: {summ.get('error')}")
        return False
    s = ms.load_samples(ms.snapshot_at(run["dir"], 0.2))
    diff = np.abs(s["rho"] - ex.sod_density(s["x"], s["time"]))
    # Both sample the same exact function at the same points; the C++ p* is good to ~1e-13
    # (docs/verification.md), so anything above 1e-9 means the two disagree about the solution.
    ok = float(diff.max()) < 1e-9
    print(f"  hvi riemann vs python Sod at t = {s['time']}: max |drho| = {diff.max():.2e} over "
          f"{diff.size} cells {'ok' if ok else 'MISMATCH'}")
    # The Tillotson tube: the python Hugoniot solution against hvi's general-EOS solver.
    run = {"dir": os.path.join(out, "al-tube-riemann"), "scene": scene.replace("sod_x", "al_impact_tube"),
           "sets": ["solver=riemann", "riemann.cells=2000", "output.vtk=false"]}
    summ = run_hvi(hvi, run, 1, reuse=False)
    if summ.get("status") != "completed":
        # Not the study's code: reported, and the study measures against the python solution.
        print(f"  WARNING: hvi riemann on al_impact_tube.toml failed: {summ.get('error')}")
        return ok
    s = ms.load_samples(ms.snapshot_at(run["dir"], 0.5))
    exact = ex.al_tube_density(s["x"], s["time"])
    diff = np.abs(s["rho"] - exact)
    # Cells whose centre lies within round-off of a shock may differ by the whole jump; count
    # the disagreeing cells instead of the largest difference.
    bad = int(np.sum(diff > 1e-6))
    good = bad <= 2
    print(f"  hvi riemann vs python Al tube: {bad} of {diff.size} cells differ by > 1e-6 "
          f"{'ok' if good else 'MISMATCH'}")
    return ok and good
