//! The boundary lookups the C API checks: ids of the boundary surface (its vertices and
//! triangles) named by the caller, with an error naming the id when it is out of range.

use crate::NONE;
use crate::chf::Chf;
use crate::error::{Error, Result};

impl Chf {
    /// [`Chf::boundary_vertex_volume_vertex`], an error when `b` is not a vertex of the
    /// boundary surface.
    pub fn checked_boundary_vertex_volume_vertex(&self, b: u32) -> Result<u32> {
        let v = self.boundary_vertex_volume_vertex(b);
        if v != NONE {
            return Ok(v);
        }
        let n = match self.boundary() {
            Some(che) => che.num_vertices(),
            None => self.boundary_surface()?.num_vertices(),
        };
        Err(Error::out_of_range(format!(
            "boundary vertex {b} out of range (the boundary surface has {n} vertices)"
        )))
    }

    /// [`Chf::boundary_triangle_half_face`], an error when `k` is not a boundary triangle.
    pub fn checked_boundary_triangle_half_face(&self, k: u32) -> Result<u32> {
        let list = self.boundary_half_faces();
        list.get(k as usize).copied().ok_or_else(|| {
            Error::out_of_range(format!(
                "boundary triangle {k} out of range (the boundary has {} triangles)",
                list.len()
            ))
        })
    }

    /// The face of boundary triangle `k`, an error when `k` is not a boundary triangle.
    pub fn checked_boundary_triangle_face(&self, k: u32) -> Result<u32> {
        Ok(self.face_of(self.checked_boundary_triangle_half_face(k)?))
    }

    /// The boundary triangle of face `f`, `NONE` for an interior face: an unpaired
    /// half-face names its face alone, a paired face is interior.
    pub fn face_boundary_triangle(&self, f: u32) -> u32 {
        let hf = self.face_half_face(f);
        if self.opposite(hf) == NONE {
            self.boundary_triangle(hf)
        } else {
            NONE
        }
    }
}
