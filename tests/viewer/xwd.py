"""A reader for X window dumps (`xwd -root`): 24- and 32-bit TrueColor
ZPixmaps, as Xvfb's screens are."""

import struct


def read(path):
    """(width, height, rgb bytes, 3 per pixel, rows top first)."""
    with open(path, "rb") as f:
        data = f.read()
    fields = struct.unpack(">25I", data[:100])
    header_size, version, pixmap_format, depth, width, height = fields[:6]
    byte_order, bits_per_pixel, bytes_per_line = fields[7], fields[11], fields[12]
    red_mask, green_mask, blue_mask = fields[14:17]
    colormap_entries = fields[19]  # ncolors
    if version != 7 or pixmap_format != 2 or bits_per_pixel not in (24, 32):
        raise ValueError(f"{path}: not a 24/32-bit ZPixmap X window dump (version {version}, format "
                         f"{pixmap_format}, {bits_per_pixel} bits per pixel)")
    pixels = data[header_size + 12 * colormap_entries:]
    step = bits_per_pixel // 8
    order = "<" if byte_order == 0 else ">"

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    rs, gs, bs = shift(red_mask), shift(green_mask), shift(blue_mask)
    rgb = bytearray(3 * width * height)
    for y in range(height):
        row = pixels[y * bytes_per_line:y * bytes_per_line + width * step]
        for x in range(width):
            chunk = row[x * step:(x + 1) * step]
            v = struct.unpack(order + "I", chunk if step == 4 else (chunk + b"\0" if order == "<" else b"\0" + chunk))[0]
            i = 3 * (y * width + x)
            rgb[i] = (v & red_mask) >> rs
            rgb[i + 1] = (v & green_mask) >> gs
            rgb[i + 2] = (v & blue_mask) >> bs
    del depth
    return width, height, bytes(rgb)
