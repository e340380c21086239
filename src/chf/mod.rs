//! CHF, the Compact Half-Face for tetrahedral meshes (being written).
