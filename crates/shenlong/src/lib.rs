//! Shenlong: instruction-based repositioning of separate 3D objects with conformal
//! geometric algebra.
