// The translation unit the test programs' shared precompiled headers are built with.
