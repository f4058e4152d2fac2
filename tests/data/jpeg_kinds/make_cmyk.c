/* Writes cmyk.jpg, a 24x16 CMYK JPEG (libjpeg-turbo), for the JPEG readers' comparison
   (tests/images/builtin_texture_read_test.cpp). Build and run:
   cc make_cmyk.c -ljpeg -o /tmp/make_cmyk && /tmp/make_cmyk */
#include <jpeglib.h>
#include <stdio.h>

int main(void) {
  const int w = 24, h = 16;
  FILE* f = fopen("cmyk.jpg", "wb");
  struct jpeg_compress_struct c;
  struct jpeg_error_mgr e;
  c.err = jpeg_std_error(&e);
  jpeg_create_compress(&c);
  jpeg_stdio_dest(&c, f);
  c.image_width = w;
  c.image_height = h;
  c.input_components = 4;
  c.in_color_space = JCS_CMYK;
  jpeg_set_defaults(&c);
  jpeg_set_quality(&c, 90, TRUE);
  jpeg_start_compress(&c, TRUE);
  unsigned char row[24 * 4];
  while (c.next_scanline < (unsigned)h) {
    int y = c.next_scanline;
    for (int x = 0; x < w; ++x) {
      row[4 * x + 0] = (unsigned char)(x * 10);
      row[4 * x + 1] = (unsigned char)(y * 15);
      row[4 * x + 2] = (unsigned char)((x + y) * 6);
      row[4 * x + 3] = (unsigned char)(255 - x * 4);
    }
    JSAMPROW r = row;
    jpeg_write_scanlines(&c, &r, 1);
  }
  jpeg_finish_compress(&c);
  jpeg_destroy_compress(&c);
  fclose(f);
  return 0;
}
