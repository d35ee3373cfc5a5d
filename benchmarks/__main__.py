"""python -m benchmarks [--quick] [--output FILE] [--fmu FILE]: see benchmarks.runner."""

import sys

from .runner import main

sys.exit(main())
