#include "io/JpegReader.h"

// jpeglib.h needs FILE and size_t declared first.
#include <cstddef>
#include <cstdio>

#include <jerror.h>
#include <jpeglib.h>

#include <csetjmp>
#include <memory>
#include <string>
#include <vector>

#include "core/Error.h"
#include "io/ByteSource.h"

namespace fm::io {

namespace {

namespace fs = std::filesystem;

// libjpeg's whole-image buffers (a progressive file's coefficients: 128 bytes per block) are
// given this much beyond what the image's blocks need; a header that asks more is refused.
constexpr long kJpegMemorySlack = 64L << 20;

// libjpeg hands its handlers the jpeg_error_mgr: it is the first member, so the handlers find
// the rest. Trivially destructible: libjpeg's errors longjmp over the frames that use it.
struct JpegErrors {
    jpeg_error_mgr manager;
    std::jmp_buf jump;
    bool endOfFile;
    char message[JMSG_LENGTH_MAX];
};

[[noreturn]] void onJpegError(j_common_ptr cinfo) {
    auto* e = reinterpret_cast<JpegErrors*>(cinfo->err);
    if (!e->message[0]) (*cinfo->err->format_message)(cinfo, e->message);
    std::longjmp(e->jump, 1);
}

// Level -1 is a warning (corrupt data, premature end of file): an error here. Trace messages
// (levels 0 and up) are dropped.
void onJpegMessage(j_common_ptr cinfo, int level) {
    if (level >= 0) return;
    auto* e = reinterpret_cast<JpegErrors*>(cinfo->err);
    if (cinfo->err->msg_code == JWRN_JPEG_EOF) e->endOfFile = true;
    onJpegError(cinfo);
}

void printNothing(j_common_ptr) {}

struct JpegRun {
    jpeg_decompress_struct cinfo;
    JpegErrors errors;
};

// Each phase has its own setjmp; libjpeg's errors land in the phase's frame, which holds only
// trivially destructible locals (the buffers belong to the caller), so the jump skips no
// destructor.
bool readHeader(JpegRun& run, std::FILE* file) {
    if (setjmp(run.errors.jump)) return false;
    jpeg_create_decompress(&run.cinfo);
    jpeg_stdio_src(&run.cinfo, file);
    jpeg_read_header(&run.cinfo, TRUE);
    return true;
}

void appendGreyRow(const JSAMPLE* row, JDIMENSION width, int components, std::vector<float>& out) {
    for (std::size_t x = 0; x < width; ++x) {
        const JSAMPLE* p = row + x * static_cast<std::size_t>(components);
        out.push_back(static_cast<float>(components == 3 ? greyOfRgb(p[0], p[1], p[2]) : p[0]));
    }
}

bool decodeRows(JpegRun& run, GreyRows& rows, std::vector<JSAMPLE>& row) {
    if (setjmp(run.errors.jump)) return false;
    jpeg_start_decompress(&run.cinfo);
    const JDIMENSION width = run.cinfo.output_width;
    const int components = run.cinfo.output_components;
    row.resize(std::size_t{width} * static_cast<std::size_t>(components));
    rows.start(width, run.cinfo.output_height);
    while (run.cinfo.output_scanline < run.cinfo.output_height) {
        JSAMPROW p = row.data();
        if (jpeg_read_scanlines(&run.cinfo, &p, 1) != 1) {
            std::snprintf(run.errors.message, sizeof run.errors.message, "no row decoded at row %u",
                          run.cinfo.output_scanline);
            return false;
        }
        appendGreyRow(row.data(), width, components, rows.pixels);
    }
    jpeg_finish_decompress(&run.cinfo);  // reads on to EOI: trailing corrupt data is refused too
    return true;
}

struct Decompressor {
    JpegRun run{};
    ~Decompressor() { jpeg_destroy_decompress(&run.cinfo); }  // safe on a half-made struct
};

std::string failure(const fs::path& path, const JpegErrors& e) {
    return quoted(path) + (e.endOfFile ? ": truncated JPEG (" : ": corrupt JPEG data (") +
           e.message + ")";
}

// Checks what the header says before anything is allocated, and sets the output and the cap
// on libjpeg's memory.
void checkHeader(jpeg_decompress_struct& c, std::uintmax_t fileSize, const fs::path& path) {
    const std::string name = quoted(path);
    checkGreyImageSize(path, c.image_width, c.image_height);
    if (c.arith_code)
        throw Error(name + ": arithmetic-coded JPEG (not supported; only Huffman-coded)");
    if (c.jpeg_color_space == JCS_GRAYSCALE && c.num_components == 1)
        c.out_color_space = JCS_GRAYSCALE;
    else if ((c.jpeg_color_space == JCS_YCbCr || c.jpeg_color_space == JCS_RGB) &&
             c.num_components == 3)
        c.out_color_space = JCS_RGB;
    else
        throw Error(name + ": JPEG with " + std::to_string(c.num_components) +
                    " components of colour space " + std::to_string(c.jpeg_color_space) +
                    " (CMYK/YCCK or unknown); grey and colour (YCbCr/RGB) JPEGs are read");
    std::uint64_t mostBlocks = 0, allBlocks = 0;
    for (int i = 0; i < c.num_components; ++i) {
        const std::uint64_t blocks =
            std::uint64_t{c.comp_info[i].width_in_blocks} * c.comp_info[i].height_in_blocks;
        mostBlocks = std::max(mostBlocks, blocks);
        allBlocks += blocks;
    }
    // Every block's DC coefficient takes a Huffman code of at least one bit.
    if (mostBlocks > 8 * std::uint64_t{fileSize})
        throw Error(
            name + ": " + std::to_string(c.image_width) + " x " + std::to_string(c.image_height) +
            " pixels cannot come from " + std::to_string(fileSize) +
            " bytes (JPEG data hold at least one bit per 8 x 8 block): corrupt or truncated JPEG");
    c.mem->max_memory_to_use = kJpegMemorySlack + static_cast<long>(allBlocks * sizeof(JBLOCK));
}

}  // namespace

GreyImage readJpeg(const fs::path& path) {
    const std::uintmax_t size = fileSize(path);
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                         std::fclose);
    if (!file) throw Error("cannot open " + quoted(path));
    Decompressor d;
    JpegRun& run = d.run;
    run.cinfo.err = jpeg_std_error(&run.errors.manager);
    run.errors.manager.error_exit = onJpegError;
    run.errors.manager.emit_message = onJpegMessage;
    run.errors.manager.output_message = printNothing;
    if (!readHeader(run, file.get())) throw Error(failure(path, run.errors));
    checkHeader(run.cinfo, size, path);
    GreyRows rows;
    std::vector<JSAMPLE> row;
    if (!decodeRows(run, rows, row)) throw Error(failure(path, run.errors));
    return rows.finish(8);
}

}  // namespace fm::io
