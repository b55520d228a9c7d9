// MeshLab's plugin interface and document types, from the release the plugin is built for:
// FilterPlugin since 2021.05, MeshFilterInterface up to 2020.09. Only the adapters and
// filter_run.cpp include this.
#pragma once

#if __has_include(<common/plugins/interfaces/filter_plugin.h>)
#include <common/plugins/interfaces/filter_plugin.h>
#define CURVATURE_INPAINT_MESHLAB_FILTER_PLUGIN 1
#else
#include <common/interfaces.h>
#define CURVATURE_INPAINT_MESHLAB_FILTER_PLUGIN 0
#endif
