"""Readers of the simulators' mesh files, written from the formats' specifications alone, for the
tests to check what the library writes: TOUGH's MESH (fixed-width ELEME and CONNE records) and
PFLOTRAN's explicit unstructured grid (.uge) with its region files."""
import functools
import re

# A Fortran E/F input field: blanks around a number, nothing else.
NUMBER = r" *[-+]?(?:\d+\.?\d*|\.\d+)(?:[EeDd][-+]?\d+)?"
ELEMENT_NAME = re.compile(r"^[A-Za-z0-9 ]{3}[ 0-9][0-9]$")
ISOT = re.compile(r"^ *[123]$")


@functools.lru_cache
def numbers_pattern(count):
    """`count` NUMBER fields joined by '|', as one expression: a record's fields matched at once."""
    return re.compile("^%s$" % "\\|".join([NUMBER] * count))


def fortran_reals(line, columns, path, number, names):
    """The Fortran E/F fields of a fixed-width record at `columns` (first, last + 1), named for
    errors."""
    fields = [line[a:b] for a, b in columns]
    if not numbers_pattern(len(fields)).match("|".join(fields)):
        bad = next(name for field, name in zip(fields, names) if not re.match("^%s$" % NUMBER, field))
        raise ValueError("%s:%d %s: %r is not a real number field" % (path, number, bad, fields[names.index(bad)]))
    return [float(field.replace("D", "E").replace("d", "e")) for field in fields]


def read_tough_mesh(path):
    """The ELEME and CONNE blocks of a TOUGH MESH file. ELEME records (TOUGH2 user's guide): name
    A3+I2 (columns 1-5), NSEQ I5, NADD I5, material A3+A2 (16-20), VOLX E10.4 (21-30), AHTX
    (31-40), PMX (41-50), X, Y, Z (51-80). CONNE records: names (1-5, 6-10), NSEQ, NAD1, NAD2,
    ISOT I5 each (11-30), D1, D2, AREAX, BETAX E10.4 (31-70). Blocks end at a blank record.
    Returns (elements: list of dicts, connections: list of dicts); raises ValueError naming the
    line of a record that breaks the format."""
    with open(path) as f:
        lines = f.read().split("\n")
    elements, connections, block = [], [], None
    for number, line in enumerate(lines, 1):
        if block is None:
            if line[:5] in ("ELEME", "CONNE"):
                block = line[:5]
            elif line.strip():
                raise ValueError("%s:%d: %r outside a block" % (path, number, line))
            continue
        if not line.strip():
            block = None
            continue
        if len(line) > 80:
            raise ValueError("%s:%d: %s record of %d columns" % (path, number, block, len(line)))
        line = line.ljust(80)
        if block == "ELEME":
            name = line[0:5]
            if not ELEMENT_NAME.match(name):
                raise ValueError("%s:%d: element name %r is not A3 and I2" % (path, number, name))
            if line[5:15].strip() or line[30:50].strip():
                raise ValueError("%s:%d: NSEQ, NADD, AHTX or PMX set" % (path, number))
            volume, x, y, z = fortran_reals(line, ((20, 30), (50, 60), (60, 70), (70, 80)), path, number,
                                            ("VOLX", "X", "Y", "Z"))
            elements.append({"name": name, "material": line[15:20], "volume": volume, "xyz": [x, y, z]})
        else:
            isot = line[25:30]
            if line[10:25].strip() or not ISOT.match(isot):
                raise ValueError("%s:%d: NSEQ, NAD1, NAD2 set or ISOT %r not 1, 2 or 3" % (path, number, isot))
            d1, d2, area, betax = fortran_reals(line, ((30, 40), (40, 50), (50, 60), (60, 70)), path, number,
                                                ("D1", "D2", "AREAX", "BETAX"))
            connections.append({"names": (line[0:5], line[5:10]), "isot": int(isot),
                                "d1": d1, "d2": d2, "area": area, "betax": betax})
    if block is not None:
        raise ValueError("%s: the %s block does not end with a blank record" % (path, block))
    return elements, connections


def read_uge(path):
    """PFLOTRAN's explicit unstructured grid: `CELLS n`, n lines `id x y z volume`, `CONNECTIONS
    m`, m lines `id1 id2 x y z area`. Returns (cells: {id: (xyz, volume)}, connections: list of
    (id1, id2, xyz, area))."""
    with open(path) as f:
        lines = [line.split() for line in f if line.strip()]
    if lines[0][0] != "CELLS":
        raise ValueError("%s: no CELLS card" % path)
    n = int(lines[0][1])
    cells = {}
    for row in lines[1:1 + n]:
        if len(row) != 5:
            raise ValueError("%s: cell record %r" % (path, row))
        cells[int(row[0])] = ([float(x) for x in row[1:4]], float(row[4]))
    if len(cells) != n or sorted(cells) != list(range(1, n + 1)):
        raise ValueError("%s: cell ids are not 1..%d" % (path, n))
    card = lines[1 + n]
    if card[0] != "CONNECTIONS":
        raise ValueError("%s: no CONNECTIONS card" % path)
    m = int(card[1])
    connections = []
    for row in lines[2 + n:]:
        if len(row) != 6:
            raise ValueError("%s: connection record %r" % (path, row))
        connections.append((int(row[0]), int(row[1]), [float(x) for x in row[2:5]], float(row[5])))
    if len(connections) != m:
        raise ValueError("%s: %d connections, the card says %d" % (path, len(connections), m))
    return cells, connections


def read_ex(path):
    """A PFLOTRAN explicit boundary region: `CONNECTIONS k`, then k lines `id x y z area`."""
    with open(path) as f:
        lines = [line.split() for line in f if line.strip()]
    if lines[0][0] != "CONNECTIONS" or int(lines[0][1]) != len(lines) - 1:
        raise ValueError("%s: the CONNECTIONS count does not match its records" % path)
    return [(int(r[0]), [float(x) for x in r[1:4]], float(r[4])) for r in lines[1:]]
