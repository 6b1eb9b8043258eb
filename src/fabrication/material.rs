//! The material a strip is cut from: Young's modulus `E`, shear modulus `G` and the allowable
//! stress the bending check compares with; presets for the usual lamella materials, or values of
//! the user's.
use super::error::FabricationError;

/// One gigapascal in pascals.
const GPA: f64 = 1e9;
/// One megapascal in pascals.
const MPA: f64 = 1e6;

/// Elastic constants and allowable stress of a strip material, in pascals.
///
/// The presets are standard engineering values, characteristic (not design) values without
/// safety or duration factors: the allowable stress is a material's characteristic strength, and
/// what margin a structure needs is the engineer's call (scale `allowable_stress` down for it).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// Name used in reports (`timber`, `plywood`, `steel`, `aluminium` or `custom`).
    pub name: String,
    /// Young's modulus `E` in Pa (along the strip).
    pub youngs_modulus: f64,
    /// Shear modulus `G` in Pa.
    pub shear_modulus: f64,
    /// Allowable (comparison) stress in Pa.
    pub allowable_stress: f64,
}

/// The names [`Material::preset`] knows.
pub const PRESET_NAMES: [&str; 4] = ["timber", "plywood", "steel", "aluminium"];

impl Material {
    /// A material of the user's; every value must be finite and positive.
    pub fn new(name: &str, youngs_modulus: f64, shear_modulus: f64, allowable_stress: f64) -> Result<Material, FabricationError> {
        let material = Material { name: name.to_string(), youngs_modulus, shear_modulus, allowable_stress };
        material.validate()?;
        Ok(material)
    }

    /// A preset by name (case-insensitive), `None` for an unknown name:
    /// - `timber`: softwood strength class C24 of EN 338 (E₀,mean 11 GPa, G_mean 0.69 GPa, bending
    ///   strength f_m,k 24 MPa);
    /// - `plywood`: birch plywood along the face grain, typical manufacturers' values after
    ///   EN 789 / EN 636 (E 9.5 GPa, G 0.62 GPa, bending strength 30 MPa);
    /// - `steel`: structural steel S355 (EN 1993-1-1: E 210 GPa, G 81 GPa, yield strength 355 MPa);
    /// - `aluminium`: EN AW-6082 T6 (EN 1999-1-1: E 70 GPa, G 27 GPa, 0.2 % proof strength 250 MPa).
    pub fn preset(name: &str) -> Option<Material> {
        let (e, g, f) = match name.to_ascii_lowercase().as_str() {
            "timber" => (11.0, 0.69, 24.0),
            "plywood" => (9.5, 0.62, 30.0),
            "steel" => (210.0, 81.0, 355.0),
            "aluminium" | "aluminum" => (70.0, 27.0, 250.0),
            _ => return None,
        };
        let canonical = if name.eq_ignore_ascii_case("aluminum") { "aluminium".to_string() } else { name.to_ascii_lowercase() };
        Some(Material { name: canonical, youngs_modulus: e * GPA, shear_modulus: g * GPA, allowable_stress: f * MPA })
    }

    /// Checks that every constant is finite and positive, naming the first that is not.
    pub fn validate(&self) -> Result<(), FabricationError> {
        for (name, value) in [("youngs_modulus", self.youngs_modulus), ("shear_modulus", self.shear_modulus), ("allowable_stress", self.allowable_stress)] {
            if !(value.is_finite() && value > 0.0) {
                return Err(FabricationError::parameter(name, format!("must be finite and > 0 Pa, got {value}")));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid_and_named() {
        for name in PRESET_NAMES {
            let material = Material::preset(name).expect("a preset");
            assert_eq!(material.name, name);
            material.validate().expect("valid constants");
            // Isotropic metals: G = E / (2 (1 + ν)) with ν ≈ 0.3; timber's G is far smaller.
            assert!(material.shear_modulus < material.youngs_modulus / 2.0);
        }
        assert_eq!(Material::preset("Aluminum").map(|m| m.name), Some("aluminium".to_string()));
        assert!(Material::preset("cheese").is_none());
    }

    #[test]
    fn user_values_are_checked() {
        assert!(Material::new("custom", 1e9, 1e8, 1e7).is_ok());
        let error = Material::new("custom", 1e9, -1.0, 1e7).expect_err("negative G");
        assert!(error.to_string().contains("shear_modulus"), "{error}");
        assert!(Material::new("custom", f64::NAN, 1e8, 1e7).is_err());
    }
}
