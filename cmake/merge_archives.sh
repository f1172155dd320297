#!/bin/sh
# merge_archives.sh AR MRI_SCRIPT: runs ar on an MRI script (cmake/library.cmake: libcurvbench.a).
exec "$1" -M < "$2"
