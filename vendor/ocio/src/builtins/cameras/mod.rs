//! Camera builtin transforms (ports of `AppleCameras.cpp`, `ArriCameras.cpp`,
//! `CanonCameras.cpp`, `PanasonicCameras.cpp`, `RedCameras.cpp` and
//! `SonyCameras.cpp`).

pub mod apple;
pub mod arri;
pub mod canon;
pub mod panasonic;
pub mod red;
pub mod sony;
