"""report.html in a real browser: Debian's Chromium, headless, opens the page of a run from disk
(no network) and reports what it laid out. Every picture must decode (complete, with its natural
size) and every table must be there with its rows: the regions of report.json, the worst cells.

Usage: test_report_in_browser.py VOROCRUST MODELS_DIR
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

VOROCRUST, MODELS = sys.argv[1:3]
CHROMIUM = shutil.which("chromium")
TABLES = ["summary", "regions", "surface-quality", "cell-quality", "cell-parts", "worst-cells", "timings"]
PICTURES = ["surface-picture", "cut-picture", "worst-cells-picture", "histograms"]

# Runs in the page once everything has loaded and writes what it found into the document, which
# Chromium's --dump-dom then prints.
PROBE = """<script>
window.addEventListener("load", () => {
  const found = {images: {}, tables: {}};
  for (const img of document.images) {
    found.images[img.id] = {complete: img.complete, width: img.naturalWidth, height: img.naturalHeight,
                            shown: img.getBoundingClientRect().width};
  }
  for (const table of document.querySelectorAll("table")) {
    found.tables[table.id] = {rows: table.rows.length, height: table.getBoundingClientRect().height};
  }
  const out = document.createElement("pre");
  out.id = "probe";
  out.textContent = JSON.stringify(found);
  document.body.appendChild(out);
});
</script>"""


class ReportInBrowser(unittest.TestCase):
    def test_every_picture_decodes_and_every_table_is_laid_out(self):
        self.assertIsNotNone(CHROMIUM, "chromium is missing: install it (scripts/install-deps.sh)")
        work = tempfile.mkdtemp(prefix="vorocrust-browser-")
        self.addCleanup(shutil.rmtree, work, True)
        out = os.path.join(work, "out")
        subprocess.run([VOROCRUST, "mesh", os.path.join(MODELS, "sandia_non_manifold_box.obj"), "-o", out,
                        "--seed", "1", "-q", "--formats", "html"], check=True)
        with open(os.path.join(out, "report.json")) as f:
            report = json.load(f)
        with open(os.path.join(out, "report.html")) as f:
            page = f.read()
        self.assertNotIn("<script", page, "the page itself runs no script")
        # The probe goes into a copy; the page the run wrote stays as it is.
        probed = os.path.join(work, "probed.html")
        with open(probed, "w") as f:
            f.write(page.replace("</body>", PROBE + "\n</body>"))
        run = subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
                              "--user-data-dir=" + os.path.join(work, "profile"), "--virtual-time-budget=20000",
                              "--dump-dom", "file://" + probed],
                             capture_output=True, text=True, timeout=300)
        self.assertEqual(run.returncode, 0, run.stderr[-2000:])
        match = re.search(r'<pre id="probe">(.*?)</pre>', run.stdout, re.S)
        self.assertIsNotNone(match, "the probe did not run: " + run.stdout[-1000:] + run.stderr[-1000:])
        found = json.loads(match.group(1).replace("&quot;", '"').replace("&amp;", "&"))

        self.assertEqual(sorted(found["images"]), sorted(PICTURES))
        for name, img in found["images"].items():
            self.assertTrue(img["complete"] and img["width"] > 100 and img["height"] > 100, "%s: %s" % (name, img))
            self.assertGreater(img["shown"], 100, name)
        for name in PICTURES[:3]:
            self.assertEqual((found["images"][name]["width"], found["images"][name]["height"]), (720, 540), name)

        self.assertEqual(sorted(found["tables"]), sorted(TABLES))
        for name, table in found["tables"].items():
            self.assertGreater(table["height"], 0, name)
            self.assertGreater(table["rows"], 1, name)
        self.assertEqual(found["tables"]["regions"]["rows"], 1 + len(report["regions"]))
        self.assertEqual(found["tables"]["worst-cells"]["rows"], 1 + min(20, report["cells"]["cells"]))
        layers = report["cells"]["quality"]["layers"]
        self.assertEqual(found["tables"]["cell-parts"]["rows"],
                         1 + 3 * ((layers["boundary_layer_cells"] > 0) + (layers["interior_cells"] > 0)))


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
