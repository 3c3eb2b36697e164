#!/usr/bin/env python3
"""Cook's membrane (samples/cooks-membrane-2d.json) on N x N meshes, full integration against B-bar: the tip's
vertical displacement and its change from the next coarser mesh — the table of docs/VALIDATION.md.

  tests/bench/run_cooks_membrane.py [BIN]      (BIN: build/app/rollsim)
"""
import json
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BIN = sys.argv[1] if len(sys.argv) > 1 else str(ROOT / "build/app/rollsim")
sys.path.insert(0, str(ROOT / "scripts"))
cooks = __import__("make-cooks-membrane")


def tip(work, n, formulation):
    deck = work / f"cook-{n}.inp"
    deck.write_text(cooks.deck(n))
    p = json.loads((ROOT / "samples/cooks-membrane-2d.json").read_text())
    p["bodies"][0]["mesh"]["file"] = str(deck)
    p["bodies"][0]["formulation"] = formulation
    f = work / f"cook-{n}-{formulation}.json"
    f.write_text(json.dumps(p))
    out = work / f"out-{n}-{formulation}"
    subprocess.run([BIN, "run", str(f), "--out", str(out), "--quiet"], check=True, stdout=subprocess.DEVNULL)
    return json.loads((out / "summary.json").read_text())["results"]["probes"]["tip"]["displacement"][1]


def main():
    with tempfile.TemporaryDirectory() as d:
        work = Path(d)
        print("| N × N | full: tip uy [mm] | B-bar: tip uy [mm] | B-bar change from N/2 |")
        print("|---|---|---|---|")
        before = None
        for n in (2, 4, 8, 16, 32, 64):
            full, bbar = tip(work, n, "full"), tip(work, n, "bbar")
            change = f"{bbar - before:+.4f}" if before is not None else "—"
            print(f"| {n} | {full:.4f} | {bbar:.4f} | {change} |")
            before = bbar


if __name__ == "__main__":
    main()
