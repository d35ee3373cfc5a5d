"""python -m benchmarks [SECTION ...] [--models MODEL ...] [--quick]: see benchmarks.runner."""

import sys

from .runner import main

sys.exit(main())
