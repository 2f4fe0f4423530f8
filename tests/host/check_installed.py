#!/usr/bin/env python3
"""host_plugin_installed: every freshly built plugin must be installed, byte-identical, in
MeshLab's plugin folder (otherwise the host tests would exercise a stale plugin).
    usage: check_installed.py PLUGIN_DIR BUILT.so [BUILT.so ...]"""
import filecmp
import os
import sys

plugin_dir, built = sys.argv[1], sys.argv[2:]
bad = 0
for so in built:
    inst = os.path.join(plugin_dir, os.path.basename(so))
    if not os.path.exists(so):
        print("NOT BUILT: %s (build first: cmake --build build)" % so)
        bad += 1
    elif not os.path.exists(inst):
        print("NOT INSTALLED: %s (run: cmake --install build)" % inst)
        bad += 1
    elif not filecmp.cmp(so, inst, shallow=False):
        print("STALE INSTALL: %s differs from the fresh build %s (run: cmake --install build)" % (inst, so))
        bad += 1
    else:
        print("ok: %s == %s" % (inst, so))
sys.exit(1 if bad else 0)
