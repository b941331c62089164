"""Reading the CSV files talus writes (a header line, then rows of numbers)."""
import csv


def read_columns(path):
    """The file as {column name: list of floats}."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    header, data = rows[0], [list(map(float, r)) for r in rows[1:] if r]
    return {name: [r[k] for r in data] for k, name in enumerate(header)}
