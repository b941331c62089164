"""ESRI ASCII grids for the generators of bundled terrain (make_*.py).

write(path, value, nx, ny, cell, x0, y0, decimals) samples value(x, y) at the
cell centres, x and y in metres from the grid's lower-left corner (x0, y0 in
map coordinates), the first line being the northern row.
"""


def write(path, value, nx, ny, cell, x0, y0, decimals):
    with open(path, "w") as f:
        f.write(f"ncols {nx}\nnrows {ny}\nxllcorner {x0}\nyllcorner {y0}\ncellsize {cell}\n")
        f.write("NODATA_value -9999\n")
        for j in range(ny):  # first line = northern row
            y = (ny - j - 0.5) * cell
            f.write(" ".join(f"{value((i + 0.5) * cell, y):.{decimals}f}" for i in range(nx)) + "\n")
