#!/usr/bin/env python3
"""Tests of scripts/check_layers.py on a tiny synthetic tree: the clean tree, which holds
every include the layers allow, passes; each injected upward or sideways include fails
with the line naming the file, the line, both layers and the header.

    python3 tests/layers/check_layers_selftest.py [-v]
"""

import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
CHECK = os.path.join(HERE, "..", "..", "scripts", "check_layers.py")

# Every allowed kind of edge once: down the common/ layers, protocol -> common,
# app -> protocol, server/core -> app, daemon and cli -> server/core, client -> app,
# client/sim -> client; tests/ and bench/ include anything.
CLEAN_TREE = {
    "common/geometry/geometry.h": ["<vector>"],
    "common/map/map.h": ['"common/geometry/geometry.h"', '"common/map/ramp.h"'],
    "common/map/ramp.h": [],
    "common/scene/scene.h": ['"common/map/map.h"'],
    "common/raycast/ray_caster.h": ['"common/scene/scene.h"'],
    "common/slicing/map_slice.h": ['"common/raycast/ray_caster.h"'],
    "common/planning/map_planner.h": ['"common/slicing/map_slice.h"'],
    "common/io/seed_format.cpp": ['"common/planning/map_planner.h"', '"common/geometry/geometry.h"',
                                  "<nlohmann/json.hpp>", "<boost/geometry.hpp>"],
    "protocol/map_store.h": ['"common/io/seed_format.cpp"', "<mysql++/mysql++.h>"],
    "app/cli_context.h": ['"protocol/map_store.h"', '"common/map/map.h"'],
    "server/core/map_cache.h": ['"app/cli_context.h"', '"protocol/map_store.h"'],
    "server/daemon/request_loop.cpp": ['"server/core/map_cache.h"', '"server/daemon/handlers/handler.h"'],
    "server/daemon/handlers/handler.h": ['"server/daemon/request_loop.h"', '"server/core/map_cache.h"'],
    "server/daemon/request_loop.h": [],
    "server/cli/map_commands.cpp": ['"server/core/map_cache.h"', '"app/cli_context.h"', "<CLI/CLI.hpp>"],
    "client/robot_client.h": ['"app/cli_context.h"', '"client/localization/pose.h"'],
    "client/localization/pose.h": ['"common/geometry/geometry.h"'],
    "client/sim/sim_robot.h": ['"client/robot_client.h"', '"client/sim/drive.h"'],
    "client/sim/drive.h": [],
    "tests/common/map_test.cpp": ['"server/cli/map_commands.cpp"', '"client/sim/sim_robot.h"'],
    "bench/bench_map.cpp": ['"server/daemon/request_loop.h"', "<mysql++/mysql++.h>"],
}


def write_tree(root, tree):
    for rel, includes in tree.items():
        path = os.path.join(root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write("// synthetic\n#pragma once\n")
            for inc in includes:
                f.write(f"#include {inc}\n")


def run_check(root):
    p = subprocess.run([sys.executable, CHECK, "--root", root], capture_output=True, text=True)
    return p.returncode, p.stdout


class CheckLayers(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.root = self.tmp.name
        write_tree(self.root, CLEAN_TREE)

    def tearDown(self):
        self.tmp.cleanup()

    def inject(self, rel, include):
        """Appends an include to rel (created if absent); returns its line number."""
        path = os.path.join(self.root, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        lines = []
        if os.path.exists(path):
            with open(path) as f:
                lines = f.read().splitlines()
        lines.append(f"#include {include}")
        with open(path, "w") as f:
            f.write("\n".join(lines) + "\n")
        return len(lines)

    def assert_fails_with(self, expected):
        rc, out = run_check(self.root)
        self.assertEqual(rc, 1, out)
        self.assertEqual(out.splitlines(), expected)

    def test_clean_tree_passes(self):
        rc, out = run_check(self.root)
        self.assertEqual(rc, 0, out)

    def test_common_geometry_including_map_fails(self):
        line = self.inject("common/geometry/geometry.h", '"common/map/map.h"')
        self.assert_fails_with(
            [f"common/geometry/geometry.h:{line}: common/geometry must not include common/map (common/map/map.h)"])

    def test_common_io_including_protocol_fails(self):
        line = self.inject("common/io/seed_format.cpp", '"protocol/map_store.h"')
        self.assert_fails_with(
            [f"common/io/seed_format.cpp:{line}: common/io must not include protocol (protocol/map_store.h)"])

    def test_common_including_mysqlpp_fails(self):
        line = self.inject("common/map/map.h", "<mysql++/mysql++.h>")
        self.assert_fails_with(
            [f"common/map/map.h:{line}: common/map must not include the database (<mysql++/mysql++.h>)"])

    def test_common_including_asio_fails(self):
        line = self.inject("common/scene/scene.h", "<boost/asio/ip/tcp.hpp>")
        self.assert_fails_with(
            [f"common/scene/scene.h:{line}: common/scene must not include the network (<boost/asio/ip/tcp.hpp>)"])

    def test_daemon_including_cli_fails(self):
        line = self.inject("server/daemon/request_loop.cpp", '"server/cli/map_commands.h"')
        self.assert_fails_with(
            [f"server/daemon/request_loop.cpp:{line}: server/daemon must not include server/cli "
             "(server/cli/map_commands.h)"])

    def test_cli_including_daemon_handler_fails(self):
        line = self.inject("server/cli/map_commands.cpp", '"server/daemon/handlers/handler.h"')
        self.assert_fails_with(
            [f"server/cli/map_commands.cpp:{line}: server/cli must not include server/daemon "
             "(server/daemon/handlers/handler.h)"])

    def test_client_including_sim_fails(self):
        line = self.inject("client/localization/pose.h", '"client/sim/sim_robot.h"')
        self.assert_fails_with(
            [f"client/localization/pose.h:{line}: client must not include client/sim (client/sim/sim_robot.h)"])

    def test_client_including_server_fails(self):
        line = self.inject("client/sim/sim_robot.h", '"server/core/map_cache.h"')
        self.assert_fails_with(
            [f"client/sim/sim_robot.h:{line}: client/sim must not include server/core (server/core/map_cache.h)"])

    def test_protocol_including_app_fails(self):
        line = self.inject("protocol/map_store.h", '"app/cli_context.h"')
        self.assert_fails_with(
            [f"protocol/map_store.h:{line}: protocol must not include app (app/cli_context.h)"])

    def test_include_beside_the_file_is_placed_by_its_folder(self):
        # "map.h" from common/geometry/ would not resolve; from common/map/ it does, and
        # an include of the scene beside it is then upward.
        self.inject("common/map/ramp.h", '"../scene/scene.h"')
        rc, out = run_check(self.root)
        self.assertEqual(rc, 1, out)
        self.assertIn("common/map must not include common/scene (../scene/scene.h)", out)

    def test_every_violation_is_reported(self):
        a = self.inject("common/geometry/geometry.h", '"common/map/map.h"')
        b = self.inject("client/robot_client.h", '"client/sim/drive.h"')
        rc, out = run_check(self.root)
        self.assertEqual(rc, 1, out)
        self.assertEqual(sorted(out.splitlines()), sorted([
            f"client/robot_client.h:{b}: client must not include client/sim (client/sim/drive.h)",
            f"common/geometry/geometry.h:{a}: common/geometry must not include common/map (common/map/map.h)",
        ]))

    def test_core_is_below_geometry(self):
        self.inject("common/core/error.h", "<stdexcept>")
        self.inject("common/geometry/geometry.h", '"common/core/error.h"')
        rc, out = run_check(self.root)
        self.assertEqual(rc, 0, out)
        line = self.inject("common/core/error.h", '"common/geometry/geometry.h"')
        self.assert_fails_with(
            [f"common/core/error.h:{line}: common/core must not include common/geometry "
             "(common/geometry/geometry.h)"])

    def test_unknown_common_folder_is_reported(self):
        self.inject("common/misc/util.h", "<vector>")
        rc, out = run_check(self.root)
        self.assertEqual(rc, 1, out)
        self.assertIn("common/misc/util.h:1: common/misc is not a known layer", out)

    def test_tests_bench_examples_fuzz_are_not_checked(self):
        for rel in ["tests/x_test.cpp", "bench/b.cpp", "examples/e.cpp", "fuzz/f.cpp"]:
            self.inject(rel, '"server/daemon/request_loop.h"')
            self.inject(rel, "<mysql++/mysql++.h>")
        rc, out = run_check(self.root)
        self.assertEqual(rc, 0, out)

    def test_product_including_tests_fails(self):
        line = self.inject("server/core/map_cache.h", '"tests/integration/test_db.h"')
        self.assert_fails_with(
            [f"server/core/map_cache.h:{line}: server/core must not include tests (tests/integration/test_db.h)"])


if __name__ == "__main__":
    unittest.main()
