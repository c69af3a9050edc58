#pragma once
// Generated volumes: the default knee phantom and analytic test objects.
#include <string>

#include "phantom/KneePhantom.h"
#include "volume/Volume.h"

namespace fm {

// By name: "knee" (the default scene) or an analytic object ("box", "sphere", "cylinder",
// "ellipsoid") with default parameters. Options may follow after commas, e.g.
// "knee,flexion=30,size=128x128x141". Throws fm::Error for an unknown name or option.
Volume makePhantom(const std::string& nameAndOptions);

// The knee phantom's parameters for "knee[,options]" (what makePhantom would build). Throws
// fm::Error for another name or a bad option.
KneePhantomParams kneePhantomParams(const std::string& nameAndOptions);

}  // namespace fm
