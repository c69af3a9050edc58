#include "core/HeapReuse.h"

#include <cstdlib>  // defines __GLIBC__ on glibc (the test below needs a libc header first)
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace fm {

void keepFreedMemoryForReuse() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 256 << 20);  // blocks below 256 MiB from the heap
    mallopt(M_TRIM_THRESHOLD, 1 << 30);    // return free heap top only beyond 1 GiB
#endif
}

}  // namespace fm
