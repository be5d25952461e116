#!/usr/bin/env bash
# Validation C: regenerate.py (the runs, the figures and README.md's table).
#   validation/cavity_packing/regenerate.sh [BUILD_DIR]
exec /usr/bin/python3 "$(dirname "$0")/regenerate.py" "$@"
