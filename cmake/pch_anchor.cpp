// The translation unit that builds the shared precompiled header of the libraries and the
// command-line tool (cmake/DynposModule.cmake).
