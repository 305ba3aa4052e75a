// The implementation of stb's PNG writer for the web build, from Debian's libstb-dev header (the desktop links
// Debian's libstb.so, which holds it already).
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
