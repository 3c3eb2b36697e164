"""What the rolling benchmark scripts share: one project run whole and read back, two run in turn and timed.

run_pass(rollsim, path, out): `rollsim run` of one project into `out`, its row — status, the travel where it became
steady, the rolling measures by summary.json's names (roll_force, roll_torque, forward_slip, mean_spread, spread,
exit_thickness, volume_change), Newton iterations, the roll's factorizations, total_s, the run's own CPU time and peak
memory (its rusage) and the pass's theory. paired_projects(rollsim, a, b, runs, tmp): the medians of projects a and b
run whole in turn (paired_timing: CPU, wall, peak memory and their ratios).
"""
import json
import os
import subprocess

import paired_timing  # beside this script

MEASURES = ("roll_force", "roll_torque", "forward_slip", "mean_spread", "spread", "exit_thickness", "volume_change")


def run_pass(rollsim, path, out):
    child = subprocess.Popen([str(rollsim), "run", str(path), "--out", str(out), "--quiet"],
                             stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    _, _, usage = os.wait4(child.pid, 0)
    s = json.loads((out / "summary.json").read_text())
    r = s.get("results", {}).get("rolling", {})
    inc = s["increments"]
    steady = r.get("steady_state_increment") or 0
    row = {k: r.get(k) for k in MEASURES}
    row.update(status=s["status"], steady_at=inc[steady - 1]["travel"] if steady else None,
               newton=sum(i.get("newton_iterations", 0) for i in inc),
               roll_factors=s.get("solver", {}).get("factorizations", {}).get("roll"), seconds=s["timing"]["total_s"],
               cpu=usage.ru_utime + usage.ru_stime, peak=usage.ru_maxrss / 1024.0, theory=r.get("theory", {}))
    return row


def paired_projects(rollsim, a, b, runs, tmp):
    def cmd(p):
        out = tmp / f"pt-{p.stem}"
        return ["sh", "-c", f"rm -rf {out}; exec {rollsim} run {p} --out {out} --quiet"]
    return {name: round(value, 4) for name, value in paired_timing.medians(cmd(a), cmd(b), runs).items()}
