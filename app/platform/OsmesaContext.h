#pragma once
// The OSMesa context alone, behind a header free of GL types: <GL/osmesa.h> pulls in <GL/gl.h>,
// which clashes with glad, so only OsmesaContext.cpp includes it.
#include <memory>
#include <vector>

namespace fm::app {

class OsmesaContext {
  public:
    using Proc = void (*)();
    // A GL 3.3 core context rendering into a width x height RGBA buffer. Throws fm::Error.
    OsmesaContext(int width, int height);
    ~OsmesaContext();
    OsmesaContext(const OsmesaContext&) = delete;
    OsmesaContext& operator=(const OsmesaContext&) = delete;

    void makeCurrent();
    static Proc procAddress(const char* name);
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    void* context_ = nullptr;
    int width_, height_;
    std::vector<unsigned char> buffer_;
};

}  // namespace fm::app
