#include "platform/OsmesaContext.h"

#include <GL/osmesa.h>

#include <string>

#include "core/Error.h"

namespace fm::app {

OsmesaContext::OsmesaContext(int width, int height)
    : width_(width), height_(height), buffer_(static_cast<std::size_t>(width) * height * 4) {
    if (width < 16 || height < 16 || width > 8192 || height > 8192)
        throw Error("headless screenshot size " + std::to_string(width) + "x" +
                    std::to_string(height) + " is out of range (16..8192 per side)");
    const int attribs[] = {OSMESA_FORMAT,
                           OSMESA_RGBA,
                           OSMESA_DEPTH_BITS,
                           24,
                           OSMESA_STENCIL_BITS,
                           8,
                           OSMESA_PROFILE,
                           OSMESA_CORE_PROFILE,
                           OSMESA_CONTEXT_MAJOR_VERSION,
                           3,
                           OSMESA_CONTEXT_MINOR_VERSION,
                           3,
                           0};
    context_ = OSMesaCreateContextAttribs(attribs, nullptr);
    if (!context_) throw Error("OSMesa: could not create a GL 3.3 core context");
    makeCurrent();
}

OsmesaContext::~OsmesaContext() {
    if (!context_) return;
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);  // release the framebuffer first
    OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

void OsmesaContext::makeCurrent() {
    if (!OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), buffer_.data(), GL_UNSIGNED_BYTE,
                           width_, height_))
        throw Error("OSMesa: could not make the context current");
}

OsmesaContext::Proc OsmesaContext::procAddress(const char* name) {
    return reinterpret_cast<Proc>(OSMesaGetProcAddress(name));
}

}  // namespace fm::app

// LeakSanitizer (sanitizer builds only reads this): Mesa and the X/GL client libraries keep a
// few hundred bytes of process-lifetime state that they never free (OSMesa leaks its
// framebuffer wrappers even after the context is released and destroyed). Suppress leaks whose
// allocation happened inside those system libraries only; our own code stays checked.
extern "C" const char* __lsan_default_suppressions() {
    return "leak:libOSMesa.so\n"
           "leak:libgallium\n"
           "leak:swrast_dri.so\n"
           "leak:libLLVM\n"
           "leak:libGLX\n"
           "leak:libGLdispatch\n"
           "leak:libX11.so\n"
           "leak:libglfw.so\n"
           "leak:libdbus\n";
}
