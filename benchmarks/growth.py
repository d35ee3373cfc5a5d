"""4. Per-step cost and memory as the run grows.

Per-step cost of the joint beside the plain floor at each run length, peak RSS
of the worker processes, and the Python heap the joint's stepping keeps.
"""

from .step_cost import LOOP_CHUNK, instantiate, side_by_side, step_loop
from .timing import against, in_fresh_process, met, us

FLAT_GOAL = 1.3  # largest / smallest cost ratio over the run lengths


def worker_tracemalloc(unzipped, steps):
    import gc
    import tracemalloc

    joint = instantiate(unzipped)
    step_loop(joint, 10)  # first-call caches are not growth
    gc.collect()
    tracemalloc.start()
    baseline = tracemalloc.get_traced_memory()[0]
    step_loop(joint, steps, 10)
    # FMPy's ctypes arrays form reference cycles: garbage the collector frees is no leak.
    gc.collect()
    current, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    joint.close()
    return {"retained_bytes": current - baseline, "peak_bytes": peak - baseline}


def growth(fmus, sizes, cost=None):
    """Per-step cost of the joint and the plain floor at each run length (the
    length of section 1 reuses its runs, `cost`, when it ran), peak RSS, and
    tracemalloc of the joint."""
    pair = {name: fmus[name] for name in ("plain", "joint")}
    rows = []
    for steps in sizes.growth_steps:
        if cost and steps == sizes.steps:
            runs = cost["loop"]
        else:
            # Short runs are cheap and noisy: as many as section 1; one long run.
            runs = side_by_side(
                "loop",
                pair,
                sizes.runs if steps < sizes.steps else 1,
                steps,
                max(1, min(LOOP_CHUNK, steps // 10)),
            )
        rows.append(
            {
                "steps": steps,
                **against(runs, "plain"),
                "peak_rss_kib": max(run["peak_rss_kib"] for run in runs),
                "peak_rss_growth_kib": max(run["peak_rss_growth_kib"] for run in runs),
            }
        )
    traced = [
        {"steps": steps, **in_fresh_process("tracemalloc", unzipped=fmus["joint"], steps=steps)}
        for steps in sizes.memory_steps
    ]
    return {"rows": rows, "traced": traced}


def growth_rows(grow):
    rows, traced = grow["rows"], grow["traced"]
    # Judged on the ratio to the floor run beside it, which the machine's load
    # cancels from; a cost that grew with the run length would raise it.
    ratios = [r["ratio"] for r in rows]
    spread = max(ratios) / min(ratios)
    return [
        "| 4. FMU2Slave loop per step at "
        + ", ".join(f"{r['steps']:,}" for r in rows)
        + " steps | "
        + ", ".join(us(r["joint"]) for r in rows)
        + "; ÷ plain floor "
        + ", ".join(f"{x:.2f}" for x in ratios)
        + f" (largest ÷ smallest {spread:.2f}) | flat (≤ {FLAT_GOAL}) | "
        f"{met(spread <= FLAT_GOAL)} |",
        "| 4. memory: peak RSS of the worker process (VmHWM) at each length; Python heap kept "
        "after "
        + ", ".join(f"{t['steps']:,}" for t in traced)
        + " steps (tracemalloc) | "
        + ", ".join(f"{r['peak_rss_kib'] / 1024:.0f} MiB" for r in rows)
        + "; "
        + ", ".join(f"{t['retained_bytes']:,} B" for t in traced)
        + f" | no growth | {met(no_memory_growth(grow))} |",
    ]


def no_memory_growth(grow):
    # The heap kept may hold caches of fixed size; a leak of even one float per
    # step (24 B) would make it grow by far more than 1 B per 10 steps.
    first, last = grow["traced"][0], grow["traced"][-1]
    kept_per_step = (last["retained_bytes"] - first["retained_bytes"]) / max(
        1, last["steps"] - first["steps"]
    )
    return kept_per_step < 0.1 and all(r["peak_rss_growth_kib"] < 16 * 1024 for r in grow["rows"])


def growth_table(grow):
    lines = [
        "| steps | runs | joint per step | plain floor per step | ratio | peak RSS (MiB) | "
        "peak RSS growth in the loop (MiB) |",
        "|---|---|---|---|---|---|---|",
    ]
    lines += [
        f"| {r['steps']:,} | {r['runs']} | {us(r['joint'])} | {us(r['floor'])} | "
        f"{r['ratio']:.2f} | {r['peak_rss_kib'] / 1024:.1f} | "
        f"{r['peak_rss_growth_kib'] / 1024:.1f} |"
        for r in grow["rows"]
    ]
    lines += [
        "",
        "| steps traced | Python heap peak during the loop | kept after the loop |",
        "|---|---|---|",
    ]
    lines += [
        f"| {t['steps']:,} | {t['peak_bytes']:,} B | {t['retained_bytes']:,} B |"
        for t in grow["traced"]
    ]
    return "\n".join(lines)
