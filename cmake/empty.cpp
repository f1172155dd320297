// The shared library libcurvbench.so is the layers linked whole (cmake/library.cmake); this
// translation unit only gives the target a source.
