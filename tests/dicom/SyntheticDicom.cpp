#include "dicom/SyntheticDicom.h"

#include <gdcmDataElement.h>
#include <gdcmDicts.h>
#include <gdcmGlobal.h>
#include <gdcmImage.h>
#include <gdcmImageWriter.h>
#include <gdcmReader.h>
#include <gdcmWriter.h>

#include <cstdio>

#include <gtest/gtest.h>

#include "io/DicomSlice.h"

namespace fm::test {
namespace {

void setText(gdcm::DataSet& ds, std::uint16_t group, std::uint16_t element, gdcm::VR vr,
             std::string value) {
    if (value.size() % 2) value += (vr == gdcm::VR::UI ? '\0' : ' ');  // DICOM even lengths
    gdcm::DataElement de(gdcm::Tag(group, element));
    de.SetVR(vr);
    de.SetByteValue(value.data(), gdcm::VL(static_cast<std::uint32_t>(value.size())));
    ds.Replace(de);
}

}  // namespace

std::int16_t syntheticStoredValue(int column, int row, int slice) {
    return static_cast<std::int16_t>(100 * slice + 10 * row + column - 50);
}

SyntheticSlice makeSyntheticSlice(int sliceIndex, double z) {
    SyntheticSlice s;
    s.position = glm::dvec3(-10.0, 20.0, z);
    s.instanceNumber = sliceIndex + 1;
    s.stored.resize(static_cast<std::size_t>(s.columns) * s.rows);
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.columns; ++c)
            s.stored[static_cast<std::size_t>(r) * s.columns + c] =
                syntheticStoredValue(c, r, sliceIndex);
    return s;
}

bool writeSyntheticSlice(const SyntheticSlice& s, const std::filesystem::path& file) {
    fm::silenceGdcmTrace();  // GDCM's own warnings are noise in test logs
    gdcm::ImageWriter writer;
    gdcm::Image& image = writer.GetImage();
    image.SetNumberOfDimensions(2);
    image.SetDimension(0, static_cast<unsigned>(s.columns));
    image.SetDimension(1, static_cast<unsigned>(s.rows));
    image.SetPixelFormat(gdcm::PixelFormat(1, 16, static_cast<unsigned short>(s.bitsStored),
                                           static_cast<unsigned short>(s.bitsStored - 1),
                                           s.isSigned ? 1 : 0));
    image.SetPhotometricInterpretation(gdcm::PhotometricInterpretation::MONOCHROME2);
    image.SetTransferSyntax(s.implicitVr ? gdcm::TransferSyntax::ImplicitVRLittleEndian
                                         : gdcm::TransferSyntax::ExplicitVRLittleEndian);
    const double origin[3] = {s.position.x, s.position.y, s.position.z};
    image.SetOrigin(origin);
    const double cosines[6] = {s.rowDirection.x,    s.rowDirection.y,    s.rowDirection.z,
                               s.columnDirection.x, s.columnDirection.y, s.columnDirection.z};
    image.SetDirectionCosines(cosines);
    image.SetSpacing(0, s.columnSpacing);
    image.SetSpacing(1, s.rowSpacing);
    image.SetSpacing(2, 1.0);
    image.SetIntercept(s.intercept);
    image.SetSlope(s.slope);

    gdcm::DataElement pixels(gdcm::Tag(0x7fe0, 0x0010));
    pixels.SetByteValue(reinterpret_cast<const char*>(s.stored.data()),
                        gdcm::VL(static_cast<std::uint32_t>(s.stored.size() * 2)));
    image.SetDataElement(pixels);

    gdcm::DataSet& ds = writer.GetFile().GetDataSet();
    setText(ds, 0x0008, 0x0016, gdcm::VR::UI, "1.2.840.10008.5.1.4.1.1.2");  // CT Image Storage
    setText(ds, 0x0008, 0x0018, gdcm::VR::UI,
            "1.2.826.0.1.3680043.2.1125.9." + std::to_string(s.instanceNumber));
    setText(ds, 0x0008, 0x0060, gdcm::VR::CS, s.modality);
    setText(ds, 0x0008, 0x103e, gdcm::VR::LO, s.seriesDescription);
    setText(ds, 0x0020, 0x000d, gdcm::VR::UI, s.studyInstanceUid);
    setText(ds, 0x0020, 0x000e, gdcm::VR::UI, s.seriesInstanceUid);
    setText(ds, 0x0020, 0x0011, gdcm::VR::IS, s.seriesNumber);
    setText(ds, 0x0020, 0x0013, gdcm::VR::IS, std::to_string(s.instanceNumber));
    if (s.pixelPadding) {
        gdcm::DataElement pad(gdcm::Tag(0x0028, 0x0120));
        pad.SetVR(gdcm::VR::SS);
        const std::int16_t value = *s.pixelPadding;
        pad.SetByteValue(reinterpret_cast<const char*>(&value), gdcm::VL(2));
        ds.Replace(pad);
    }
    writer.SetFileName(file.string().c_str());
    if (!writer.Write()) {
        ADD_FAILURE() << "GDCM could not write the synthetic slice " << file;
        return false;
    }
    // GDCM writes a 2-D image's origin without its z: set ImagePositionPatient ourselves.
    char position[128];
    std::snprintf(position, sizeof position, "%.10g\\%.10g\\%.10g", s.position.x, s.position.y,
                  s.position.z);
    return editDicomElement(file, 0x0020, 0x0032, std::string(position));
}

bool editDicomElement(const std::filesystem::path& file, std::uint16_t group, std::uint16_t element,
                      const std::optional<std::string>& value) {
    gdcm::Reader reader;
    reader.SetFileName(file.string().c_str());
    if (!reader.Read()) {
        ADD_FAILURE() << "cannot re-read " << file;
        return false;
    }
    gdcm::DataSet& ds = reader.GetFile().GetDataSet();
    const gdcm::Tag tag(group, element);
    if (value) {
        const gdcm::Dicts& dicts = gdcm::Global::GetInstance().GetDicts();
        setText(ds, group, element, dicts.GetDictEntry(tag).GetVR(), *value);
    } else {
        ds.Remove(tag);
    }
    gdcm::Writer writer;
    writer.SetFile(reader.GetFile());
    writer.SetFileName(file.string().c_str());
    if (!writer.Write()) {
        ADD_FAILURE() << "cannot rewrite " << file;
        return false;
    }
    return true;
}

}  // namespace fm::test
