#pragma once
// Mutual information of two images' intensities (Viola & Wells 1997; Maes et al. 1997), the
// usual similarity across contrasts (T1 against T2, MR against CT): it rewards any consistent
// relation between the two intensities, not only a linear one. Only pixels inside `mask` count.
//
// A joint histogram of `bins` x `bins` over each image's own range on the mask; every pixel
// pair is spread over the four nearest bin pairs by its fractional bin positions (bilinear,
// "partial volume" style), which keeps the measure continuous in the pose. In nats, >= 0.
#include "core/Image.h"
#include "similarity/Mask.h"

namespace fm {

inline constexpr int kDefaultMutualInformationBins = 32;

// 0 when fewer than two pixels count or either image is constant over them. Throws fm::Error
// if the sizes differ or bins is outside 2..1024.
double mutualInformation(const Image& a, const Image& b, const Mask* mask = nullptr,
                         int bins = kDefaultMutualInformationBins);

}  // namespace fm
