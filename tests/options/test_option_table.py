#!/usr/bin/env python3
"""The option table reaches the command line and the Python module with the same names,
defaults and ranges: `vorocrust options --json` (the library's table) against `vorocrust mesh
--help`, the signature, docstring and OPTIONS of vorocrust.mesh(), and against what each front end
refuses. (The MeshLab filter's parameters are checked by tests/meshlab/test_filter_parameters.cpp,
the FreeCAD object's properties by tests/freecad/freecad_app_test.py.)

Run by CTest as: python3 test_option_table.py VOROCRUST_CLI PYTHON_PACKAGE_DIR MODELS_DIR
"""
import inspect
import json
import math
import os
import re
import subprocess
import sys
import unittest

CLI, PACKAGE, MODELS = sys.argv[1:4]
del sys.argv[1:4]
sys.path.insert(0, PACKAGE)
import vorocrust  # noqa: E402

TABLE = json.loads(subprocess.run([CLI, "options", "--json"], capture_output=True, text=True, check=True).stdout)
MODEL = os.path.join(MODELS, "sandia_OneBox.obj")


def cli(*args):
    return subprocess.run([CLI, *args], capture_output=True, text=True, timeout=300)


def outside_values(o):
    """Values just outside an option's range (numbers), or not among its choices."""
    if o["kind"] in ("integer", "real"):
        values = []
        if o["min"] is not None:
            values.append(o["min"] if o["min_open"] else o["min"] - 1)
        if o["max"] is not None:
            values.append(o["max"] if o["max_open"] else o["max"] + 1)
        return [v for v in values if v != o["also"] and v != o["unset_number"]]
    if o["kind"] == "choice":
        return ["nonesuch"]
    return []


class OptionTable(unittest.TestCase):
    def test_every_option_in_the_clis_help_with_its_default_and_range(self):
        help_text = cli("mesh", "--help").stdout
        for o in TABLE:
            with self.subTest(option=o["name"]):
                self.assertIn("cli", o["front_ends"])
                line = next((l for l in help_text.splitlines() if re.match(r"\s*" + re.escape(o["cli"]) + r"\b", l)), None)
                self.assertIsNotNone(line, o["cli"])
                # A long flag's help may begin on the next line.
                at = help_text.index(line)
                text = help_text[at:help_text.find("\n  -", at + 1)]
                self.assertIn(o["default_text"][len("default: "):], text)
                if o["kind"] != "flag":
                    self.assertIn("range: " + o["range_text"], text)

    def test_mesh2d_takes_the_options_the_table_marks(self):
        help_text = cli("mesh2d", "--help").stdout
        marked = [o for o in TABLE if o["mesh2d"]]
        self.assertEqual(sorted(o["name"] for o in marked), sorted(vorocrust.PLANE_OPTIONS))
        for o in TABLE:
            with self.subTest(option=o["name"]):
                offered = re.search(r"^\s*" + re.escape(o["cli"]) + r"\b", help_text, re.M) is not None
                self.assertEqual(offered, o["mesh2d"], help_text)

    def test_the_readmes_list_of_options_is_what_the_program_prints(self):
        # The README shows `vorocrust options` as a block; it must not fall behind the table.
        readme = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "README.md")
        with open(readme) as f:
            blocks = re.findall(r"```\n(--lipschitz .*?)```", f.read(), re.S)
        self.assertEqual(len(blocks), 1, "the README's block of options (starting with --lipschitz)")
        printed = cli("options").stdout
        if blocks[0].strip() != printed.strip():
            import difflib
            self.fail("README.md's options differ from `vorocrust options`:\n" + "\n".join(
                difflib.unified_diff(blocks[0].strip().splitlines(), printed.strip().splitlines(), "README.md",
                                     "vorocrust options", lineterm="")))

    def test_every_option_a_keyword_of_mesh_with_its_default(self):
        signature = inspect.signature(vorocrust.mesh).parameters
        doc = vorocrust.mesh.__doc__
        by_name = {o["name"]: o for o in vorocrust.OPTIONS}
        for o in TABLE:
            with self.subTest(option=o["name"]):
                self.assertIn(o["name"], signature)
                default = signature[o["name"]].default
                self.assertEqual(list(default) if isinstance(default, (list, tuple)) else default, o["default"])
                self.assertEqual(vorocrust.DEFAULT_OPTIONS[o["name"]], default)
                python = by_name[o["name"]]
                # The same entry, but for the texts that name other options, spelled for Python.
                for key, value in o.items():
                    if key not in ("help", "default_text"):
                        self.assertEqual(python[key], value, key)
                self.assertIn("    %s: " % o["name"], doc)
                if o["kind"] != "flag":
                    self.assertIn(o["range_text"].split(" ")[-1], doc)

    def test_both_refuse_what_lies_outside_the_range_with_one_message(self):
        self.assertGreaterEqual(sum(len(outside_values(o)) for o in TABLE), 15)
        for o in TABLE:
            for value in outside_values(o):
                with self.subTest(option=o["name"], value=value):
                    text = str(int(value)) if o["kind"] == "integer" else repr(value) if o["kind"] == "real" else value
                    r = cli("mesh", MODEL, "-o", os.path.join(os.environ.get("TMPDIR", "/tmp"), "unused"),
                            o["cli"], text, "-q")
                    self.assertEqual(r.returncode, 2, r.stderr)
                    with self.assertRaises(vorocrust.UsageError) as caught:
                        vorocrust.mesh(MODEL, **{o["name"]: int(value) if o["kind"] == "integer" else value})
                    python = str(caught.exception)
                    self.assertTrue(python.startswith(o["name"] + " "), python)
                    # The CLI says the same, naming the option as its flag.
                    self.assertIn(o["cli"] + python[len(o["name"]):], r.stderr)

    def test_the_smooth_preset_changes_the_same_defaults_everywhere(self):
        preset = {o["name"]: o["smooth_default"] for o in TABLE if o["smooth_default"] is not None}
        self.assertEqual(sorted(preset), ["min_triangle_angle", "sharp_angle", "smoothing_iterations"])
        for name in preset:
            o = next(o for o in TABLE if o["name"] == name)
            self.assertIsNone(o["default"])  # unset: it follows the mode
            self.assertIn("with --smooth", o["default_text"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
