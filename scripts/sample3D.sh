#!/bin/sh
# sample3D - the SAMPLE-3D driver (thesis Appendix B, SAMPLE3D(L)).
# Placeholder until splat, bleach and etch exist (issue 8).
set -eu
echo "sample3D: the simulation programs are not built yet" >&2
exit 1
