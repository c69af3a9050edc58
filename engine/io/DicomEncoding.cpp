#include "io/DicomEncoding.h"

#include <gdcmTransferSyntax.h>

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace fm {
namespace {

std::uint16_t littleEndian16(const unsigned char* p) {
    return static_cast<std::uint16_t>(p[0] | (p[1] << 8));
}

// gdcm::VR::GetVRType on the two bytes as a C string: a known VR, or "??" (GDCM's INVALID,
// which is not its "no VR" answer, so ReadCompat takes such a data set for explicit VR).
bool gdcmSeesAVr(const char vr[2]) {
    return isKnownVr(vr) || (vr[0] == '?' && vr[1] == '?');
}

}  // namespace

std::string tagText(std::uint16_t group, std::uint16_t element) {
    char text[16];
    std::snprintf(text, sizeof text, "(%04X,%04X)", group, element);
    return text;
}

bool isKnownVr(const char vr[2]) {
    static const char* const kAll[] = {"AE", "AS", "AT", "CS", "DA", "DS", "DT", "FL", "FD",
                                       "IS", "LO", "LT", "OB", "OD", "OF", "OL", "OV", "OW",
                                       "PN", "SH", "SL", "SQ", "SS", "ST", "SV", "TM", "UC",
                                       "UI", "UL", "UN", "UR", "US", "UT", "UV"};
    for (const char* v : kAll)
        if (vr[0] == v[0] && vr[1] == v[1]) return true;
    return false;
}

std::string describe(DicomEncoding encoding) {
    return std::string(encoding.explicitVr ? "explicit" : "implicit") + " VR " +
           (encoding.bigEndian ? "big" : "little") + " endian";
}

std::string gdcmTransferSyntaxUid(const char* value, std::size_t length) {
    std::string uid(value, strnlen(value, length));
    while (!uid.empty() && uid.back() == ' ') uid.pop_back();
    return uid;
}

DicomEncodingChoice encodingOfTransferSyntax(const std::string& uid) {
    DicomEncodingChoice choice;
    const gdcm::TransferSyntax ts(gdcm::TransferSyntax::GetTSType(uid.c_str()));
    if (ts == gdcm::TransferSyntax::TS_END) {
        choice.problem = "unknown transfer syntax '" + uid + "' in (0002,0010)";
        return choice;
    }
    if (ts == gdcm::TransferSyntax::DeflatedExplicitVRLittleEndian) {
        choice.problem = "deflated transfer syntax is not supported";
        return choice;
    }
    // GDCM's table, not the UID's name: its GE private "implicit big endian" is read as
    // implicit VR little endian.
    choice.encoding.explicitVr = !ts.IsImplicit();
    choice.encoding.bigEndian = ts.GetSwapCode() == gdcm::SwapCode::BigEndian;
    if (!choice.encoding.explicitVr && choice.encoding.bigEndian)
        choice.problem = "transfer syntax " + uid + " is implicit VR big endian (not readable)";
    return choice;
}

DicomEncodingChoice guessedEncoding(const unsigned char* first, std::size_t size) {
    DicomEncodingChoice choice;
    if (size < 6) {
        choice.problem = "too short for a DICOM data set";
        return choice;
    }
    const std::uint16_t group = littleEndian16(first);
    const std::uint16_t element = littleEndian16(first + 2);
    const char vr[2] = {char(first[4]), char(first[5])};
    const bool explicitVr = gdcmSeesAVr(vr);
    // The branches of gdcm::FileMetaInformation::ReadCompat, in its order.
    if (group == 0x0008) {
        choice.encoding = {explicitVr, false};
    } else if (group == 0x0800) {
        choice.encoding = {true, true};
        if (!explicitVr) choice.problem = "implicit VR big endian (ACR-NEMA) is not readable";
    } else if (element == 0x0010) {  // a private creator
        choice.encoding = {explicitVr, false};
    } else if (explicitVr) {
        choice.encoding = {true, group > 0xff || element > 0xff};
    } else {
        choice.problem = "no file meta group, and its first element " + tagText(group, element) +
                         " gives no encoding GDCM can read";
    }
    return choice;
}

}  // namespace fm
