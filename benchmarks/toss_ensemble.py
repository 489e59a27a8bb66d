"""Coin-toss ensembles for three thicknesses: wall time on this machine and the outcome
frequencies (docs/motion.md).  Run: PYTHONPATH=src python benchmarks/toss_ensemble.py N WORKERS"""

import json
import sys
import time

import rollingdisk as rd
from rollingdisk.scenarios.toss import toss_ensemble

if __name__ == "__main__":
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    workers = int(sys.argv[2]) if len(sys.argv) > 2 else 2
    max_wall = float(sys.argv[3]) if len(sys.argv) > 3 else 20.0
    for h in (0.1, 0.3, 0.6):
        t = time.perf_counter()
        res = toss_ensemble(rd.Disk(h), n, 2024, workers=workers, max_wall=max_wall,
                            results=f"/tmp/toss_h{h}_n{n}.jsonl")
        print(json.dumps({"h": h, "n": n, "workers": workers, "max_wall": max_wall,
                          "wall_s": round(time.perf_counter() - t, 1),
                          "counts": res.counts,
                          "edge_95": [round(x, 4) for x in res.interval("edge")]}),
              flush=True)
