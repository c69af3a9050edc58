#include "similarity/Similarity.h"

#include "core/Error.h"
#include "similarity/EdgeDistance.h"
#include "similarity/GradientDifference.h"
#include "similarity/GradientNcc.h"
#include "similarity/MutualInformation.h"
#include "similarity/Ncc.h"

namespace fm {

const char* toString(SimilarityMeasure measure) {
    switch (measure) {
        case SimilarityMeasure::Ncc:
            return "ncc";
        case SimilarityMeasure::GradientNcc:
            return "gncc";
        case SimilarityMeasure::GradientDifference:
            return "gd";
        case SimilarityMeasure::MutualInformation:
            return "mi";
        case SimilarityMeasure::EdgeDistance:
            return "edge";
    }
    return "?";
}

SimilarityMeasure parseSimilarityMeasure(const std::string& text) {
    if (text == "ncc") return SimilarityMeasure::Ncc;
    if (text == "gncc" || text == "gradient-ncc") return SimilarityMeasure::GradientNcc;
    if (text == "gd" || text == "gradient-difference") return SimilarityMeasure::GradientDifference;
    if (text == "mi" || text == "mutual-information") return SimilarityMeasure::MutualInformation;
    if (text == "edge" || text == "edge-distance") return SimilarityMeasure::EdgeDistance;
    throw Error("unknown similarity measure '" + text + "' (expected ncc, gncc, gd, mi or edge)");
}

PreparedReference prepareReference(const Image& reference, SimilarityMeasure measure) {
    PreparedReference p;
    p.image = reference;
    if (measure == SimilarityMeasure::EdgeDistance)
        p.edgeDistance = distanceToMask(strongEdges(reference));
    else if (measure != SimilarityMeasure::Ncc && measure != SimilarityMeasure::MutualInformation)
        p.gradients = sobel(reference);
    return p;
}

const Image& measuredPlane(SimilarityMeasure measure, const PreparedReference& reference) {
    switch (measure) {
        case SimilarityMeasure::EdgeDistance:
            return reference.edgeDistance;
        case SimilarityMeasure::GradientNcc:
        case SimilarityMeasure::GradientDifference:
            return reference.gradients.gx;
        case SimilarityMeasure::Ncc:
        case SimilarityMeasure::MutualInformation:
            break;
    }
    return reference.image;
}

double similarity(SimilarityMeasure measure, const PreparedReference& reference,
                  const Image& moving, const Mask* mask) {
    const Image& ref = measuredPlane(measure, reference);
    if (ref.width != moving.width || ref.height != moving.height)
        throw Error("similarity: the moving image size differs from the reference size");
    if (mask && (mask->width != ref.width || mask->height != ref.height))
        throw Error("similarity: the mask size differs from the reference size");
    switch (measure) {
        case SimilarityMeasure::Ncc:
            return ncc(ref, moving, mask);
        case SimilarityMeasure::MutualInformation:
            return mutualInformation(ref, moving, mask);
        case SimilarityMeasure::GradientNcc:
            return gradientNcc(reference.gradients, sobel(moving),
                               interiorMask(ref.width, ref.height, mask));
        case SimilarityMeasure::GradientDifference:
            return gradientDifference(reference.gradients, sobel(moving),
                                      interiorMask(ref.width, ref.height, mask));
        case SimilarityMeasure::EdgeDistance:
            return edgeDistanceSimilarity(reference.edgeDistance, moving, mask);
    }
    return 0.0;
}

}  // namespace fm
