// CMeshO, MeshLab's mesh type, from the release the build is made against: 2020.09 declares it
// in common/ml_mesh_type.h, 2021.05 and later in common/ml_document/cmesh.h.
#pragma once

#if __has_include(<common/ml_document/cmesh.h>)
#include <common/ml_document/cmesh.h>
#else
#include <common/ml_mesh_type.h>
#endif
