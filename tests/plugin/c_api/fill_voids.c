/* A C program using the installed mcmd package: fills the voids of band 1
 * of a raster in place with MCMDFillNodata() and checks that none is left.
 * Usage: fill_voids file.tif */
#include <stdio.h>
#include <stdlib.h>

#include "cpl_string.h"
#include "gdal.h"
#include "mcmd_gdal.h"

static int count_voids(GDALRasterBandH band, double nodata) {
  const int w = GDALGetRasterBandXSize(band), h = GDALGetRasterBandYSize(band);
  double *row = malloc(sizeof(double) * (size_t)w);
  int voids = 0;
  for (int y = 0; y < h; ++y) {
    if (GDALRasterIO(band, GF_Read, 0, y, w, 1, row, w, 1, GDT_Float64, 0, 0) != CE_None) voids = -1;
    for (int x = 0; x < w && voids >= 0; ++x) voids += row[x] == nodata;
  }
  free(row);
  return voids;
}

int main(int argc, char **argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: fill_voids file.tif\n");
    return 2;
  }
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen(argv[1], GA_Update);
  if (!ds) return 1;
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const int before = count_voids(band, nodata);
  char **options = CSLSetNameValue(NULL, "METHOD", "mcmd");
  options = CSLSetNameValue(options, "NUM_THREADS", "2");
  const CPLErr err = MCMDFillNodata(band, NULL, options, GDALDummyProgress, NULL);
  CSLDestroy(options);
  const int after = count_voids(band, nodata);
  GDALClose(ds);
  printf("mcmd %s: %d void cells before, %d after\n", MCMDVersion(), before, after);
  return err == CE_None && has_nodata && before > 0 && after == 0 ? 0 : 1;
}
