"""Design sweep of the UniversalJoint FMU on Dask: bend angle x input speed x
crosspiece inertia distribution (the paper's T1..T4 of I0).

A thin script over `cardan_joint.sweep` (the `cardan-joint sweep` command runs
the same code). By default a LocalCluster of 2 worker processes, 1 thread each;
`--scheduler tcp://host:8786` uses a running cluster (workers must reach the
FMU at the same path and import cardan_joint); `--serial` runs in this
process; `--compare` runs both, checks the tables are identical and prints
the wall times and the speed-up.

    python build_fmu.py && python examples/design_sweep.py [--compare --repeat 2]

Writes results/design_sweep.csv (and .parquet if pyarrow is installed) and
results/design_sweep.png; each case is saved as it finishes in
results/design_sweep.cases/, and running the command again after an
interruption computes only the missing cases (--fresh to start over).
"""

import sys

from cardan_joint.sweep import main

if __name__ == "__main__":
    sys.exit(main())
