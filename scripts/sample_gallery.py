#!/usr/bin/env python3
"""Put hillshades side by side in one PNG, left to right, 6-pixel white gaps.

Usage: sample_gallery.py OUT.png HILLSHADE.png...  (same size, single band)
The first command of the README uses it to show the sample's voids and each
fill mode next to each other.
"""
import sys

import numpy as np
from osgeo import gdal

gdal.UseExceptions()


def main(out, inputs):
    images = [gdal.Open(path).ReadAsArray() for path in inputs]
    gap = np.full((images[0].shape[0], 6), 255, dtype=np.uint8)
    row = np.concatenate([part for image in images for part in (image, gap)][:-1], axis=1)
    mem = gdal.GetDriverByName('MEM').Create('', row.shape[1], row.shape[0], 1, gdal.GDT_Byte)
    mem.GetRasterBand(1).WriteArray(row)
    gdal.GetDriverByName('PNG').CreateCopy(out, mem)


if __name__ == '__main__':
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
