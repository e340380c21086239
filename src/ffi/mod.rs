//! The extern "C" layer (being written).
