"""What the tests that run meshlabserver share: a private prefix holding the plugin under test,
meshlabserver run under xvfb-run, and filter scripts (.mlx) made from the library's option table.
"""
import json
import os
import shutil
import subprocess

FAILED = 255  # meshlabserver's exit(-1), after a filter in its script fails


def make_prefix(work, meshlabserver, meshlab_lib_dir, plugin):
    """A private prefix in `work`: a copy of the installed meshlabserver in PREFIX/bin (a copy, not
    a link: MeshLab finds its plugins from the real path of its binary), with PREFIX/LIBDIR/meshlab
    holding links to the installed libmeshlab-common.so and stock plugins, and to `plugin`.
    Returns its meshlabserver and its plugins folder."""
    server = os.path.realpath(meshlabserver)
    root = os.path.dirname(os.path.dirname(server))  # /usr for /usr/bin/meshlabserver
    lib_dir = os.path.realpath(meshlab_lib_dir)
    prefix = os.path.join(work, "prefix")
    prefix_lib = os.path.join(prefix, os.path.relpath(lib_dir, root))  # PREFIX/lib/<triplet>/meshlab
    os.makedirs(os.path.join(prefix, "bin"))
    os.makedirs(os.path.join(prefix_lib, "plugins"))
    copy = os.path.join(prefix, "bin", os.path.basename(server))
    shutil.copy2(server, copy)
    os.symlink(os.path.join(lib_dir, "libmeshlab-common.so"), os.path.join(prefix_lib, "libmeshlab-common.so"))
    ours = os.path.basename(plugin)
    stock = os.path.join(lib_dir, "plugins")
    for name in sorted(os.listdir(stock)):
        if name.endswith(".so") and name != ours:  # an installed copy of ours must not shadow the one under test
            os.symlink(os.path.join(stock, name), os.path.join(prefix_lib, "plugins", name))
    os.symlink(os.path.realpath(plugin), os.path.join(prefix_lib, "plugins", ours))
    return copy, os.path.join(prefix_lib, "plugins")


def run_meshlabserver(server, work, *arguments):
    """Runs meshlabserver under xvfb-run in `work` (HOME there, so no settings of the user's);
    returns the finished process, its output (stdout and stderr) in .stdout."""
    env = dict(os.environ, HOME=os.path.join(work, "home"))
    os.makedirs(env["HOME"], exist_ok=True)
    for attempt in range(3):
        r = subprocess.run(["xvfb-run", "-a", server, *arguments], stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, text=True, errors="replace", env=env,
                           cwd=work, timeout=1800)
        # Two servers may race for a display; and xvfb-run may fail to remove its own temporary
        # folder, when its exit status (5) replaces meshlabserver's: either way, run it again.
        if not any(trouble in r.stdout for trouble in (
                "Xvfb failed to start", "xvfb-run: error: problem while cleaning up temporary directory")):
            break
    return r


def option_table(cli):
    """The library's option table, as `vorocrust options --json` prints it."""
    return json.loads(subprocess.run([cli, "options", "--json"], capture_output=True, text=True, check=True).stdout)


def option_rows(options, names, values):
    """The <Param> rows of the options `names` of the table `options`, at their defaults but for `values`
    (by option name; formats a list of names). Unset defaults are the table's unset_number, or an
    empty text."""
    rows = []
    for o in options:
        if o["name"] not in names or "meshlab" not in o["front_ends"]:
            continue
        key, value = o["meshlab"], values.get(o["name"], o["default"])
        if value is None:
            value = o["unset_number"] if o["unset_number"] is not None else ""
        if o["kind"] == "flag":
            rows.append(f'  <Param type="RichBool" name="{key}" value="{str(value).lower()}"/>')
        elif o["kind"] == "integer":
            rows.append(f'  <Param type="RichInt" name="{key}" value="{int(value)}"/>')
        elif o["kind"] == "real":
            rows.append(f'  <Param type="RichFloat" name="{key}" value="{float(value)!r}"/>')
        elif o["kind"] == "choice":
            choices = " ".join(f'enum_val{k}="{c}"' for k, c in enumerate(o["choices"]))
            rows.append(f'  <Param type="RichEnum" name="{key}" value="{o["choices"].index(value)}" '
                        f'enum_cardinality="{len(o["choices"])}" {choices}/>')
        elif o["kind"] == "choices":
            for c in o["choices"]:
                rows.append(f'  <Param type="RichBool" name="{key}{c[0].upper() + c[1:]}" value="{str(c in value).lower()}"/>')
        elif o["kind"] == "file":
            rows.append(f'  <Param type="RichOpenFile" name="{key}" value="{value}" exts_cardinality="0"/>')
        else:
            rows.append(f'  <Param type="RichString" name="{key}" value="{value}"/>')
    return rows


def script(path, filter_name, rows):
    """A MeshLab filter script (.mlx) applying one filter. meshlabserver 2020.09 aborts on a
    script that leaves out a parameter of the filter, so the callers give them all."""
    with open(path, "w") as f:
        f.write("<!DOCTYPE FilterScript>\n<FilterScript>\n"
                f' <filter name="{filter_name}">\n' + "\n".join(rows) + "\n </filter>\n</FilterScript>\n")
    return path


