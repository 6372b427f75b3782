//! A water body (Case-1 chlorophyll or a Jerlov type) and its properties per sRGB channel, for the
//! renderer's per-pixel use.

use glam::DVec3;

use crate::colour::{band_average, srgb_band_weights};
use crate::error::OpticsError;
use crate::iop::{Chlorophyll, Iops, case1_iops};
use crate::jerlov::{DarlesWater, JerlovType};
use crate::subsurface::{irradiance_reflectance, lambertian_floor_radiance, refracted_ray_radiance};

/// What defines a [`WaterBody`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WaterKind {
    /// Case-1 water of a given chlorophyll: every property from the Morel model.
    Case1,
    /// A Jerlov type: `K_d` from Jerlov's table; `a`, `b`, `b_b` from the Case-1 model at the
    /// type's equivalent chlorophyll ([`JerlovType::equivalent_chlorophyll`]).
    Jerlov(JerlovType),
}

/// A body of natural water.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaterBody {
    kind: WaterKind,
    chl: Chlorophyll,
}

impl std::str::FromStr for WaterBody {
    type Err = OpticsError;

    /// A water body by name: a Jerlov type (`I`, `IA`, `IB`, `II`, `III`, `1C`, `3C`, `5C`, `7C`,
    /// `9C`, case-insensitive, see [`JerlovType`]) or one of Darles et al.'s classes (`clear`,
    /// `turbid`, `very-turbid`, see [`DarlesWater`]).
    ///
    /// # Errors
    /// [`OpticsError::UnknownName`] listing the accepted names.
    fn from_str(name: &str) -> Result<Self, OpticsError> {
        Ok(match name.trim().to_ascii_lowercase().as_str() {
            "clear" => Self::darles(DarlesWater::Clear),
            "turbid" => Self::darles(DarlesWater::Turbid),
            "very-turbid" => Self::darles(DarlesWater::VeryTurbid),
            _ => Self::jerlov(name.parse::<JerlovType>().map_err(|_| OpticsError::UnknownName {
                name: "water_type",
                value: name.to_owned(),
                expected: "I, IA, IB, II, III, 1C, 3C, 5C, 7C, 9C, clear, turbid or very-turbid",
            })?),
        })
    }
}

impl WaterBody {
    /// Case-1 water of chlorophyll `c_mg_m3` (mg m⁻³, `[0, 100]`).
    ///
    /// # Errors
    /// [`OpticsError::OutOfRange`] outside the range.
    pub fn case1(c_mg_m3: f64) -> Result<Self, OpticsError> {
        Ok(Self { kind: WaterKind::Case1, chl: Chlorophyll::new(c_mg_m3)? })
    }

    /// Water of a Jerlov type (fits the equivalent chlorophyll once, about 10⁴ operations).
    pub fn jerlov(t: JerlovType) -> Self {
        Self { kind: WaterKind::Jerlov(t), chl: Chlorophyll(t.equivalent_chlorophyll()) }
    }

    /// The Darles et al. "clear / turbid / very turbid" water, through Brine's Jerlov mapping.
    pub fn darles(w: DarlesWater) -> Self {
        Self::jerlov(w.jerlov())
    }

    /// What defines this water.
    pub fn kind(&self) -> WaterKind {
        self.kind
    }

    /// The chlorophyll the IOPs use (mg m⁻³): the given one, or a Jerlov type's equivalent.
    pub fn chlorophyll_mg_m3(&self) -> f64 {
        self.chl.mg_m3()
    }

    /// The inherent optical properties at one wavelength.
    ///
    /// # Arguments
    /// - `lambda_nm`: wavelength (nm), `[400, 700]`; clamped.
    ///
    /// # Returns
    /// [`Iops`] (m⁻¹); see [`WaterKind`] for where each comes from.
    ///
    /// # References
    /// [`case1_iops`]; [`JerlovType::kd`].
    pub fn iops(&self, lambda_nm: f64) -> Iops {
        let mut iops = case1_iops(lambda_nm, self.chl);
        if let WaterKind::Jerlov(t) = self.kind {
            iops.k_d = t.kd(lambda_nm);
        }
        iops
    }

    /// Where `a`, `b`, `b_b` come from, in words (for reports and JSON).
    pub fn iop_source(&self) -> String {
        match self.kind {
            WaterKind::Case1 => {
                format!("Case-1 model (Morel 1988/1991, Premoze & Ashikhmin 2001) at C = {} mg/m3", self.chl.mg_m3())
            }
            WaterKind::Jerlov(t) => format!(
                "Case-1 model at the chlorophyll {:.4} mg/m3 whose Morel K_d best fits Jerlov type {t} (Brine's fit, rms log error {:.3})",
                self.chl.mg_m3(),
                t.equivalent_fit_rms()
            ),
        }
    }

    /// Where `K_d` comes from, in words.
    pub fn kd_source(&self) -> String {
        match self.kind {
            WaterKind::Case1 => "Morel 1988 K_w + chi C^e (Table 2)".to_owned(),
            WaterKind::Jerlov(t) => format!("Jerlov 1976 Table XXVII, type {t}"),
        }
    }
}

/// How spectral properties become R, G, B values.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RgbBands {
    /// One wavelength per channel (nm), R, G, B (e.g. 650, 550, 450).
    Wavelengths([f64; 3]),
    /// Averages over 400–700 nm weighted by the clipped linear-sRGB channel sensitivities
    /// ([`crate::srgb_band_weights`]).
    SrgbAverage,
}

/// Water properties per linear-sRGB channel (x = R, y = G, z = B), precomputed once per scene.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaterRgb {
    /// Absorption `a` (m⁻¹).
    pub a: DVec3,
    /// Scattering `b` (m⁻¹).
    pub b: DVec3,
    /// Backscattering `b_b` (m⁻¹).
    pub b_b: DVec3,
    /// Beam attenuation `c = a + b` (m⁻¹).
    pub c: DVec3,
    /// Diffuse attenuation `K_d` (m⁻¹).
    pub k_d: DVec3,
    /// Irradiance reflectance just below the surface `R(0⁻) = 0.33 b_b/a` (averaged as a
    /// spectrum, not computed from the averaged `a` and `b_b`).
    pub reflectance: DVec3,
}

impl WaterRgb {
    /// The channel values of `water`.
    ///
    /// With [`RgbBands::SrgbAverage`] each channel is the band average of the spectral quantity
    /// (`c` of `a + b`). Averages are exact for quantities that enter the image linearly (`R`),
    /// and first-order for the coefficients in exponents: over long paths a channel is dominated
    /// by its least-attenuated wavelengths, so the average overestimates its attenuation there.
    ///
    /// # References
    /// See [`WaterBody::iops`], [`irradiance_reflectance`] and [`crate::srgb_band_weights`].
    pub fn new(water: &WaterBody, bands: RgbBands) -> Self {
        let per = |f: &dyn Fn(&Iops) -> f64| -> DVec3 {
            match bands {
                RgbBands::Wavelengths(l) => DVec3::from_array(l.map(|l| f(&water.iops(l)))),
                RgbBands::SrgbAverage => {
                    let w = srgb_band_weights();
                    DVec3::from_array(band_average(&w, |l| f(&water.iops(l))))
                }
            }
        };
        let a = per(&|i| i.a);
        let b = per(&|i| i.b);
        Self {
            a,
            b,
            b_b: per(&|i| i.b_b),
            c: a + b,
            k_d: per(&|i| i.k_d),
            reflectance: per(&|i| irradiance_reflectance(i.b_b, i.a)),
        }
    }

    /// Diffuse upwelling radiance just below the surface, `L_df(0) = R E_d(0⁻)/π`, per channel.
    ///
    /// # Arguments
    /// - `e_d_below`: downwelling irradiance just below the surface (klx per channel), `≥ 0`.
    ///
    /// # Returns
    /// `L_df(0)` (kcd m⁻² per channel).
    pub fn diffuse_upwelling_radiance(&self, e_d_below: DVec3) -> DVec3 {
        self.reflectance * e_d_below / std::f64::consts::PI
    }

    /// Upwelling radiance just below the surface along a refracted ray, per channel (see
    /// [`refracted_ray_radiance`]).
    ///
    /// # Arguments
    /// - `e_d_below`: downwelling irradiance just below the surface (per channel), `≥ 0`.
    /// - `cos_theta`: cosine of the ray's zenith angle in water, `[0, 1]`.
    /// - `path_m`: path length to the floor along the ray (m), or `f64::INFINITY`.
    /// - `floor_radiance`: radiance leaving the floor (per channel).
    ///
    /// # Returns
    /// `L(0, θ)` per channel, in the unit of `e_d_below` per steradian.
    pub fn refracted_ray_radiance(
        &self,
        e_d_below: DVec3,
        cos_theta: f64,
        path_m: f64,
        floor_radiance: DVec3,
    ) -> DVec3 {
        let l = self.diffuse_upwelling_radiance(e_d_below);
        DVec3::new(
            refracted_ray_radiance(l.x, self.c.x, self.k_d.x, cos_theta, path_m, floor_radiance.x),
            refracted_ray_radiance(l.y, self.c.y, self.k_d.y, cos_theta, path_m, floor_radiance.y),
            refracted_ray_radiance(l.z, self.c.z, self.k_d.z, cos_theta, path_m, floor_radiance.z),
        )
    }

    /// Radiance leaving a Lambertian floor of albedo `albedo` at depth `depth_m`, per channel
    /// (see [`lambertian_floor_radiance`]).
    pub fn lambertian_floor_radiance(&self, albedo: DVec3, e_d_below: DVec3, depth_m: f64) -> DVec3 {
        DVec3::new(
            lambertian_floor_radiance(albedo.x, e_d_below.x, self.k_d.x, depth_m),
            lambertian_floor_radiance(albedo.y, e_d_below.y, self.k_d.y, depth_m),
            lambertian_floor_radiance(albedo.z, e_d_below.z, self.k_d.z, depth_m),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn water_bodies_parse_by_name() {
        assert_eq!("ib".parse::<WaterBody>().unwrap(), WaterBody::jerlov(JerlovType::IB));
        assert_eq!("Very-Turbid".parse::<WaterBody>().unwrap(), WaterBody::darles(DarlesWater::VeryTurbid));
        assert_eq!("3C".parse::<WaterBody>().unwrap(), WaterBody::jerlov(JerlovType::Coastal3));
        let e = "muddy".parse::<WaterBody>().unwrap_err().to_string();
        assert!(e.contains("water_type") && e.contains("very-turbid"), "{e}");
    }
}
