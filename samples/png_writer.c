// The one translation unit that holds stb_image_write's implementation (PNG encoding for
// render.c). It is compiled with warnings off: the code is not ours.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
