// Compiled only to build the precompiled header every static library reuses
// (cmake/motorbench.cmake: mb_pch).
