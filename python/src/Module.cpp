// fluoromatch's engine as a Python module (docs/python.md): `import fluoromatch as fm`.
// Errors are fluoromatch.Error (a RuntimeError) carrying the engine's message, which names the
// file and field; long work runs with the GIL released.
#include "Bindings.h"
#include "camera/CameraFile.h"
#include "core/Error.h"

PYBIND11_MODULE(_fluoromatch, m) {
    m.doc() = "fluoromatch: exact DRRs and 2D/3D registration of X-ray images to CT and meshes";
    static pybind11::exception<fm::Error> error(m, "Error", PyExc_RuntimeError);
    pybind11::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const fm::Error& e) {
            PyErr_SetString(error.ptr(), e.what());
        }
    });
    fm::py::bindVolume(m);
    fm::py::bindGeometry(m);
    fm::py::bindPoses(m);
    fm::py::bindMesh(m);
    fm::py::bindDrr(m);
    fm::py::bindRadiograph(m);
    fm::py::bindImages(m);
    fm::py::bindRegister(m);
    fm::py::bindTrack(m);
}
