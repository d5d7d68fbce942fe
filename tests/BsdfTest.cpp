// The BSDFs of shaders/bsdf*.glsl, run on the GPU through the BSDF probe (renderer/probes/BsdfProbe.h),
// checked against the conventions of shaders/bsdf_common.glsl:
//   - sampled directions follow bsdfPdf (chi-square against counts integrated from the GPU pdf,
//     never from the sampler), failed samples and delta lobes in bins of their own;
//   - a sample's pdf and weight agree with bsdfPdf and bsdfF re-evaluated at its direction;
//   - white furnace: the directional albedo never exceeds 1, is 1 for the lossless models, and the
//     Monte Carlo estimate agrees with a quadrature of f |cos|;
//   - glass reflects with the exact Fresnel probability and refracts by Snell's law;
//   - the reflection models are reciprocal;
//   - no NaN or Inf anywhere, down to wo in the surface and roughness 0.
#include <ptview/probes/BsdfProbe.h>
#include "ChiSquare.h"
#include "GlTestContext.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <functional>
#include <limits>
#include <ostream>
#include <random>
#include <string>
#include <vector>

namespace ptview {
namespace {

using testing::ChiSquareResult;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kSignificance = 0.01; // for the whole file, Sidak-corrected per chi-square test
constexpr int kChiSquareSamples = 400000;
constexpr int kFurnaceSamples = 200000;      // per incident direction
constexpr double kWoAzimuth = 0.9;           // wo's phi: off the axes, so no symmetry hides a bug
constexpr int kMaxProbeItems = 1 << 22;      // per GPU pass (a 1024 x 4096 target)

// PTVIEW_BSDF_TEST_SHADER_DIR, if set, points the tests at another copy of shaders/: to check
// that they catch a deliberate bug without touching the tree that others build and test from.
const BsdfProbe& probe() {
    testing::glContext();
    static const BsdfProbe instance(std::getenv("PTVIEW_BSDF_TEST_SHADER_DIR") ? std::getenv("PTVIEW_BSDF_TEST_SHADER_DIR")
                                                                               : PTVIEW_SHADER_DIR);
    return instance;
}

// ---- Materials and directions

const char* typeName(MaterialType type) {
    switch (type) {
    case MaterialType::Diffuse: return "diffuse";
    case MaterialType::Emitter: return "emitter";
    case MaterialType::DiffuseTransmission: return "diffuse_transmission";
    case MaterialType::Mirror: return "mirror";
    case MaterialType::SpecularTransmission: return "specular_transmission";
    case MaterialType::Glass: return "glass";
    case MaterialType::Metal: return "metal";
    case MaterialType::Plastic: return "plastic";
    case MaterialType::Principled: return "principled";
    case MaterialType::Medium: return "medium";
    }
    return "?";
}

Material makeMaterial(MaterialType type, float roughness = 0.0f, float ior = 1.5f, glm::vec3 color = glm::vec3(1.0f)) {
    Material material;
    material.name = typeName(type);
    material.type = type;
    material.color = color;
    material.ior = ior;
    material.roughness = roughness;
    material.radiance = type == MaterialType::Emitter ? glm::vec3(1.0f) : glm::vec3(0.0f);
    return material;
}

Material makePrincipled(float metallic, float roughness, glm::vec3 color = glm::vec3(1.0f), float transmission = 0.0f) {
    Material material = makeMaterial(MaterialType::Principled, roughness, 1.5f, color);
    material.metallic = metallic;
    material.transmission = transmission;
    return material;
}

// "principled_m0.5_t0" in front of the labels' roughness and ior, so that cases differ by name.
std::string typeLabel(const Material& material) {
    if (material.type != MaterialType::Principled) return typeName(material.type);
    char label[64];
    std::snprintf(label, sizeof label, "principled_m%g_t%g", double(material.metallic), double(material.transmission));
    return label;
}

// The direction with cos(theta) = cosTheta at azimuth phi, in the local frame.
glm::vec3 directionAt(double cosTheta, double phi = kWoAzimuth) {
    double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return glm::vec3(float(sinTheta * std::cos(phi)), float(sinTheta * std::sin(phi)), float(cosTheta));
}

double ggxAlpha(double roughness) { return roughness * roughness; }
// The product treats alpha < 1e-3 as perfectly smooth (ggxIsEffectivelySmooth); the GPU squares
// the float roughness in float, and so do we here.
bool isSmooth(float roughness) { return roughness * roughness < 1e-3f; }

double channelMean(glm::vec3 v) { return (double(v.x) + double(v.y) + double(v.z)) / 3.0; }
double luminance(glm::dvec3 rgb) { return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z; }

std::string testName(std::string text) {
    for (char& c : text)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return text;
}

std::string cosLabel(double cosTheta) {
    char text[32];
    std::snprintf(text, sizeof text, "cos%s%g", cosTheta < 0.0 ? "m" : "", std::abs(cosTheta));
    return testName(text);
}

// GPU evaluation in passes of bounded size; one wo for all wi.
std::vector<BsdfProbeValue> evaluateAll(const Material& material, glm::vec3 wo, const std::vector<glm::vec3>& wis) {
    std::vector<BsdfProbeValue> values;
    values.reserve(wis.size());
    for (std::size_t begin = 0; begin < wis.size(); begin += kMaxProbeItems) {
        std::size_t end = std::min(wis.size(), begin + std::size_t(kMaxProbeItems));
        std::vector<glm::vec3> wiPart(wis.begin() + long(begin), wis.begin() + long(end));
        std::vector<glm::vec3> woPart(wiPart.size(), wo);
        std::vector<BsdfProbeValue> part = probe().evaluate(material, woPart, wiPart);
        values.insert(values.end(), part.begin(), part.end());
    }
    return values;
}

// ---- Independent references (double precision, textbook forms)

// Unpolarized Fresnel reflectance of a smooth dielectric from the angles (Fresnel's sine and
// tangent laws), for light on the side whose normal gives cosThetaI, the other side having
// relative index eta (n_inside / n_outside; inverted when cosThetaI < 0, i.e. from inside).
double fresnelReference(double cosThetaI, double eta) {
    double n1 = 1.0, n2 = eta;
    if (cosThetaI < 0.0) std::swap(n1, n2);
    double thetaI = std::acos(std::min(1.0, std::abs(cosThetaI)));
    double sinThetaT = n1 / n2 * std::sin(thetaI);
    if (sinThetaT >= 1.0) return 1.0;
    double thetaT = std::asin(sinThetaT);
    if (thetaI < 1e-9) return std::pow((n1 - n2) / (n1 + n2), 2.0);
    if (thetaI == thetaT) return 0.0; // index matched
    double s = std::sin(thetaI - thetaT) / std::sin(thetaI + thetaT);
    double p = std::tan(thetaI - thetaT) / std::tan(thetaI + thetaT);
    return 0.5 * (s * s + p * p);
}

// Plastic picks its coat with probability F / (F + (1 - F) luminance(albedo)).
double plasticCoatProbabilityReference(const Material& material, double cosThetaO) {
    double coat = fresnelReference(std::abs(cosThetaO), material.ior);
    double base = (1.0 - coat) * luminance(glm::dvec3(material.color));
    return coat + base > 0.0 ? coat / (coat + base) : 1.0;
}

// Principled picks its parts (plastic, glass, metal) in proportion to weight x max(albedo
// estimate, 0.05) (bsdf_principled.glsl); when smooth, the delta share is the plastic's coat
// (its own coat probability) and the whole metal part.
double principledDeltaProbabilityReference(const Material& material, double cosThetaO) {
    const double m = material.metallic, t = material.transmission;
    const double weights[3] = {(1.0 - m) * (1.0 - t), (1.0 - m) * t, m};
    const double coat = fresnelReference(std::abs(cosThetaO), material.ior);
    const glm::dvec3 base(material.color);
    const double x5 = std::pow(1.0 - std::abs(cosThetaO), 5.0);
    const double albedo[3] = {coat + (1.0 - coat) * luminance(base), luminance(base),
                              luminance(base + (glm::dvec3(1.0) - base) * x5)};
    double p[3], total = 0.0;
    for (int i = 0; i < 3; ++i) total += p[i] = weights[i] * std::max(albedo[i], 0.05);
    return (p[0] * plasticCoatProbabilityReference(material, cosThetaO) + p[1] + p[2]) / total;
}

// GGX reflection pdf (visible normals, height-correlated Smith) at the float directions given,
// in double: what bsdfPdf of a metal would be without rounding.
double ggxReflectionPdfReference(glm::dvec3 wo, glm::dvec3 wi, double alpha) {
    if (wo.z < 0.0) {
        wo.z = -wo.z;
        wi.z = -wi.z;
    }
    if (wo.z <= 0.0 || wi.z <= 0.0) return 0.0;
    glm::dvec3 h = glm::normalize(wo + wi);
    double a2 = alpha * alpha;
    double d = a2 / (kPi * std::pow(h.x * h.x + h.y * h.y + h.z * h.z * a2, 2.0));
    double tan2 = (wo.x * wo.x + wo.y * wo.y) / (wo.z * wo.z);
    double g1 = 1.0 / (1.0 + 0.5 * (std::sqrt(1.0 + a2 * tan2) - 1.0));
    return g1 * d / (4.0 * wo.z);
}

// Half an ulp of x: the largest rounding error of a float of that magnitude.
double halfUlp(float x) {
    float magnitude = std::abs(x);
    return 0.5 * double(std::nextafter(magnitude, std::numeric_limits<float>::infinity()) - magnitude);
}

// How much rounding wi to float can move the GGX pdf, relatively: sum over the components of
// |d ln pdf / d wi_k| times half an ulp of wi_k, with the pdf computed as the shader does
// (h = normalize(wo + wi), wi not renormalized; by central differences of the reference).
double ggxPdfRoundingBound(glm::dvec3 wo, glm::vec3 wiFloat, double alpha) {
    const glm::dvec3 wi(wiFloat);
    const double pdf = ggxReflectionPdfReference(wo, wi, alpha);
    if (pdf <= 0.0) return 0.0;
    double bound = 0.0;
    for (int k = 0; k < 3; ++k) {
        double rounding = halfUlp(wiFloat[k]), step = 1e-3 * rounding;
        glm::dvec3 plus = wi, minus = wi;
        plus[k] += step;
        minus[k] -= step;
        double derivative = (ggxReflectionPdfReference(wo, plus, alpha) - ggxReflectionPdfReference(wo, minus, alpha)) /
                            (2.0 * step * pdf);
        bound += std::abs(derivative) * rounding;
    }
    return bound;
}

// ---- Charts: coordinates (s, phi) in [0, 1] x [0, 2 pi) on the sphere of wi, with
// d omega(wi) = jacobian(s, phi) ds dphi, to bin samples and integrate densities in.

class Chart {
public:
    virtual ~Chart() = default;
    // The direction at (s, phi) and the Jacobian there; false where the chart holds no direction
    // (its integrand is 0 there).
    virtual bool direction(double s, double phi, glm::dvec3& wi, double& jacobian) const = 0;
    // The coordinates of wi; false outside the chart.
    virtual bool coordinates(glm::dvec3 wi, double& s, double& phi) const = 0;
    virtual const char* coordinateName() const = 0;
};

// The whole sphere in (z = cos theta, phi) as in WarpTest, s = (z + 1) / 2: d omega = 2 ds dphi.
// Right for the Lambertian lobes, whose density is linear in z.
class SphereChart : public Chart {
public:
    bool direction(double s, double phi, glm::dvec3& wi, double& jacobian) const override {
        double z = 2.0 * s - 1.0, r = std::sqrt(std::max(0.0, 1.0 - z * z));
        wi = {r * std::cos(phi), r * std::sin(phi), z};
        jacobian = 2.0;
        return true;
    }
    bool coordinates(glm::dvec3 wi, double& s, double& phi) const override {
        s = 0.5 * (wi.z + 1.0);
        phi = std::atan2(wi.y, wi.x);
        if (phi < 0.0) phi += kTwoPi;
        return true;
    }
    const char* coordinateName() const override { return "(z+1)/2"; }
};

// For GGX lobes, however narrow: wi charted by its half vector h = normalize(wo + wi), in polar
// coordinates (theta, psi) about the macro normal on wo's side, psi measured from wo's azimuth.
// Reflection about h maps h one to one onto wi, with d omega(wi) = 4 (wo.h) d omega(h). In h the
// GGX lobe is centred on the normal with width alpha whatever the incidence (at grazing incidence
// it is a thin sliver in wi, but not in h), so rings placed by the GGX distribution resolve it at
// every alpha:
//   - psi: shifted by phiShift (half a wedge of the binning) so that the plane of incidence runs
//     through the middle of a wedge rather than along an edge;
//   - theta: only up to the horizon of wi, 2 (wo.h) h.z = wo.z, i.e. theta_max(psi) = pi/4 +
//     atan2(sin(theta_o) cos(psi), cos(theta_o)) / 2, so that no bin is cut by the horizon (wi
//     below it are failed samples, with their own bin) and the chart holds exactly the support;
//   - s = C(theta) / C(theta_max(psi)) with C the CDF in theta of a mixture of GGX normal
//     distributions D(h) cos(theta_h): half of it of the lobe's width alpha, the other half
//     spread over widths 10 alpha, 100 alpha, ... up to 1 and a uniform density in solid angle.
//     At normal incidence the first rings then hold equal shares of the lobe (the innermost has
//     radius ~alpha / 5), and the ladder of widths lets the rings grow smoothly through the
//     lobe's tail to a Lambertian base and the horizon: with the lobe's CDF alone, its tail
//     would be squeezed into a sliver of a ring where the Jacobian jumps by orders of magnitude,
//     and a midpoint rule would misplace whatever else (a Lambertian base) lies there.
// Within a bin the integrand is then smooth, and a midpoint rule of a few points per bin is
// accurate.
class HalfVectorChart : public Chart {
public:
    HalfVectorChart(glm::vec3 woLocal, double alpha, double phiShift = 0.0)
        : side_(woLocal.z < 0.0f ? -1.0 : 1.0), wo_(woLocal.x, woLocal.y, std::abs(double(woLocal.z))),
          phiShift_(phiShift), phiO_(std::atan2(double(woLocal.y), double(woLocal.x))) {
        wo_ = glm::normalize(wo_);
        sinThetaO_ = std::hypot(wo_.x, wo_.y);
        widths_ = {alpha};
        for (double width = 10.0 * alpha; width > 0.0 && width < 1.0; width *= 10.0) widths_.push_back(width);
        if (alpha < 1.0) widths_.push_back(1.0);
        // The lobe's width gets half the weight; the wider ones and the uniform density share the rest.
        weights_.assign(widths_.size(), 0.5 / double(widths_.size()));
        weights_[0] = 0.5;
        uniformWeight_ = 0.5 / double(widths_.size());
        if (widths_.size() == 1) uniformWeight_ = 0.5;
    }

    bool direction(double s, double phi, glm::dvec3& wi, double& jacobian) const override {
        const double psi = phi - phiShift_;
        const double thetaMax = horizon(psi), cdfMax = cdf(thetaMax);
        const double theta = inverseCdf(s * cdfMax, thetaMax);
        const double sinTheta = std::sin(theta), cosTheta = std::cos(theta);
        glm::dvec3 h(sinTheta * std::cos(psi + phiO_), sinTheta * std::sin(psi + phiO_), cosTheta);
        double woDotH = glm::dot(wo_, h);
        if (woDotH <= 0.0) return false;
        wi = 2.0 * woDotH * h - wo_;
        wi.z *= side_;
        // d omega(h) = sin(theta) dtheta dpsi, dtheta = cdfMax ds / C'(theta), C' = sin(theta) K.
        jacobian = cdfMax / cdfDensityOverSin(theta) * 4.0 * woDotH;
        return true;
    }

    bool coordinates(glm::dvec3 wi, double& s, double& phi) const override {
        wi.z *= side_;
        if (wi.z <= 0.0) return false;
        glm::dvec3 h = glm::normalize(wo_ + wi);
        const double theta = std::atan2(std::hypot(h.x, h.y), h.z);
        double psi = std::atan2(h.y, h.x) - phiO_;
        s = std::min(cdf(theta) / cdf(horizon(psi)), 1.0); // wi just above the horizon: rounding
        phi = psi + phiShift_;
        phi -= kTwoPi * std::floor(phi / kTwoPi);
        return true;
    }
    const char* coordinateName() const override { return "s_h"; }

private:
    double horizon(double psi) const {
        return 0.25 * kPi + 0.5 * std::atan2(sinThetaO_ * std::cos(psi), wo_.z);
    }
    // GGX of width a: CDF tan^2 / (a^2 + tan^2), density 2 a^2 sin cos / (sin^2 + a^2 cos^2)^2.
    double cdf(double theta) const {
        double sin2 = std::pow(std::sin(theta), 2.0), cos2 = std::pow(std::cos(theta), 2.0);
        double value = uniformWeight_ * 2.0 * std::pow(std::sin(0.5 * theta), 2.0); // 1 - cos(theta)
        for (std::size_t k = 0; k < widths_.size(); ++k)
            value += weights_[k] * sin2 / (sin2 + widths_[k] * widths_[k] * cos2);
        return value;
    }
    double cdfDensityOverSin(double theta) const {
        double sin2 = std::pow(std::sin(theta), 2.0), cosTheta = std::cos(theta);
        double value = uniformWeight_;
        for (std::size_t k = 0; k < widths_.size(); ++k) {
            double a2 = widths_[k] * widths_[k], denominator = sin2 + a2 * cosTheta * cosTheta;
            value += weights_[k] * 2.0 * a2 * cosTheta / (denominator * denominator);
        }
        return value;
    }
    // C(theta) = target on [0, thetaMax]: Newton's method kept inside a shrinking bracket.
    double inverseCdf(double target, double thetaMax) const {
        double lo = 0.0, hi = thetaMax, theta = 0.5 * thetaMax;
        for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
            double value = cdf(theta) - target;
            if (value == 0.0) return theta;
            (value < 0.0 ? lo : hi) = theta;
            double step = value / (std::sin(theta) * cdfDensityOverSin(theta));
            double next = theta - step;
            theta = (next > lo && next < hi && std::isfinite(next)) ? next : 0.5 * (lo + hi);
        }
        return theta;
    }

    double side_;
    glm::dvec3 wo_;
    double phiShift_, phiO_, sinThetaO_ = 0.0;
    std::vector<double> widths_, weights_;
    double uniformWeight_ = 0.0;
};

struct Binning {
    const Chart* chart;
    int binsS = 32;
    int binsPhi = 32;

    int size() const { return binsS * binsPhi; }

    int binOf(glm::dvec3 wi) const {
        double s, phi;
        if (!chart->coordinates(wi, s, phi)) return -1;
        if (!(s >= 0.0 && s <= 1.0 && phi >= 0.0 && phi <= kTwoPi)) return -1;
        int is = std::min(int(s * binsS), binsS - 1);
        int ip = std::min(int(phi / kTwoPi * binsPhi), binsPhi - 1);
        return ip * binsS + is;
    }

    std::string label(std::size_t bin) const {
        if (bin >= std::size_t(size())) return bin == std::size_t(size()) ? "failed samples" : "delta lobe";
        double ds = 1.0 / binsS, dp = 360.0 / binsPhi;
        char text[96];
        std::snprintf(text, sizeof text, "%s [%.4g, %.4g) phi [%.4g, %.4g) deg", chart->coordinateName(),
                      double(bin % binsS) * ds, double(bin % binsS + 1) * ds, double(bin / binsS) * dp,
                      double(bin / binsS + 1) * dp);
        return text;
    }
};

// The integral over each bin of integrand(f, pdf at wi), by a midpoint rule of sub x sub points
// per bin evaluated on the GPU. The charts keep the integrand smooth within a bin (no horizon
// through it, lobes resolved), where the rule's error falls as 1 / sub^2: at 8 x 8 the pdfs
// checked (metal and plastic at alpha 0.001 to 1, normal to grazing incidence) integrate to
// within 1e-4 of their values at 32 x 32.
using Integrand = std::function<double(const BsdfProbeValue&, const glm::dvec3& wi)>;

std::vector<double> integrateBins(const Material& material, glm::vec3 wo, const Binning& binning, int sub,
                                  const Integrand& integrand) {
    const double ds = 1.0 / binning.binsS, dphi = kTwoPi / binning.binsPhi;
    const double cell = ds * dphi / double(sub * sub);
    std::vector<glm::vec3> wis;
    std::vector<glm::dvec3> wisExact;
    std::vector<double> weights;
    wis.reserve(std::size_t(binning.size()) * std::size_t(sub * sub));
    for (int bin = 0; bin < binning.size(); ++bin) {
        const int is = bin % binning.binsS, ip = bin / binning.binsS;
        for (int j = 0; j < sub; ++j)
            for (int i = 0; i < sub; ++i) {
                glm::dvec3 wi(0.0, 0.0, 1.0);
                double jacobian = 0.0;
                if (!binning.chart->direction((is + (i + 0.5) / sub) * ds, (ip + (j + 0.5) / sub) * dphi, wi, jacobian))
                    jacobian = 0.0;
                wis.push_back(glm::vec3(glm::normalize(wi)));
                wisExact.push_back(wi);
                weights.push_back(jacobian * cell);
            }
    }
    std::vector<BsdfProbeValue> values = evaluateAll(material, wo, wis);
    std::vector<double> integral(std::size_t(binning.size()), 0.0);
    for (std::size_t p = 0; p < values.size(); ++p)
        if (weights[p] > 0.0) integral[p / std::size_t(sub * sub)] += integrand(values[p], wisExact[p]) * weights[p];
    return integral;
}

double pdfIntegrand(const BsdfProbeValue& value, const glm::dvec3&) { return double(value.pdfSolidAngle); }
double projectedFIntegrand(const BsdfProbeValue& value, const glm::dvec3& wi) {
    return channelMean(value.f) * std::abs(wi.z) / glm::length(wi);
}

// The chart to integrate a model's non-delta part in: GGX lobes by their half vector, the rest
// (Lambertian lobes, and the smooth plastic's base) on the (z, phi) sphere.
bool usesHalfVectorChart(const Material& material) {
    return (material.type == MaterialType::Metal || material.type == MaterialType::Plastic ||
            material.type == MaterialType::Principled) &&
           !isSmooth(material.roughness);
}

// ---- 1. Chi-square: sampled directions follow bsdfPdf

struct LobeCase {
    Material material;
    double cosThetaO = 1.0;
    std::string label;
    std::uint32_t seed = 0;
};

void PrintTo(const LobeCase& lobe, std::ostream* out) { *out << lobe.label; }

// Roughness for alpha = 0.001 (just rough: 0.0317^2 = 0.0010049), 0.05, 0.3 and 1.
const std::vector<float> kRoughRoughness = {0.0317f, 0.2236068f, 0.5477226f, 1.0f};
const std::vector<double> kLobeCosines = {0.999, 0.7, 0.3, 0.02, -0.5};

// Every model with a non-delta sampled part: Lambertian reflection and transmission, metal and
// plastic at every rough alpha, and the smooth plastic (whose non-delta part is its base).
const std::vector<LobeCase>& lobeCases() {
    static const std::vector<LobeCase> cases = [] {
        std::vector<Material> materials = {makeMaterial(MaterialType::Diffuse, 0.0f, 1.5f, {0.8f, 0.6f, 0.4f}),
                                           makeMaterial(MaterialType::DiffuseTransmission, 0.0f, 1.5f, {0.8f, 0.6f, 0.4f})};
        for (float roughness : kRoughRoughness)
            materials.push_back(makeMaterial(MaterialType::Metal, roughness, 1.5f, {0.9f, 0.6f, 0.3f}));
        materials.push_back(makeMaterial(MaterialType::Plastic, 0.0f, 1.5f, {0.7f, 0.5f, 0.3f}));
        for (float roughness : kRoughRoughness)
            materials.push_back(makeMaterial(MaterialType::Plastic, roughness, 1.5f, {0.7f, 0.5f, 0.3f}));
        // Principled: metallic 0, 0.5, 1 from smooth (roughness 1e-3: a delta coat over the base)
        // to rough; the fully metallic smooth one is a delta lobe only (BsdfFurnace covers it).
        for (float metallic : {0.0f, 0.5f, 1.0f})
            for (float roughness : {1e-3f, 0.0317f, 0.5477226f, 1.0f})
                if (!(metallic == 1.0f && isSmooth(roughness)))
                    materials.push_back(makePrincipled(metallic, roughness, {0.8f, 0.5f, 0.3f}));
        std::vector<LobeCase> list;
        for (const Material& material : materials)
            for (double cosThetaO : kLobeCosines) {
                char label[96];
                std::snprintf(label, sizeof label, "%s_r%g_%s", typeLabel(material).c_str(), double(material.roughness),
                              cosLabel(cosThetaO).c_str());
                list.push_back({material, cosThetaO, testName(label), 0});
            }
        for (std::size_t i = 0; i < list.size(); ++i) list[i].seed = 7000u + std::uint32_t(i);
        return list;
    }();
    return cases;
}

class BsdfLobe : public ::testing::TestWithParam<LobeCase> {};

// Bins: the chart's 32 x 32, then failed samples (pdf 0), then the delta lobe (smooth plastic's
// coat). Expected counts: N times the GPU pdf integrated over each bin; N times the delta lobe's
// probability from the reference Fresnel; the failures get what is left, 1 - (integral of the
// pdf) - (delta probability), which is not 0 for GGX lobes that reach below the horizon.
TEST_P(BsdfLobe, SamplesFollowThePdf) {
    const LobeCase& lobe = GetParam();
    const Material& material = lobe.material;
    const glm::vec3 wo = directionAt(lobe.cosThetaO);
    SphereChart sphere;
    HalfVectorChart halfVector(wo, ggxAlpha(material.roughness), kPi / 32.0);
    const Binning binning{usesHalfVectorChart(material) ? static_cast<const Chart*>(&halfVector) : &sphere, 32, 32};
    const std::size_t failedBin = std::size_t(binning.size()), deltaBin = failedBin + 1;
    const bool principled = material.type == MaterialType::Principled;
    const bool hasDelta = (material.type == MaterialType::Plastic || principled) && isSmooth(material.roughness);
    const double deltaProbability = !hasDelta ? 0.0
                                    : principled ? principledDeltaProbabilityReference(material, wo.z)
                                                 : plasticCoatProbabilityReference(material, wo.z);

    std::vector<double> observed(deltaBin + 1, 0.0);
    int outside = 0, badDelta = 0;
    for (const BsdfProbeSample& sample : probe().sample(material, {wo}, kChiSquareSamples, lobe.seed)) {
        if (sample.pdfSolidAngle == 0.0f) {
            observed[failedBin] += 1.0;
        } else if (sample.isDelta) {
            observed[deltaBin] += 1.0;
            // The coat's mirror direction, chosen with the coat's probability, weighted F / P.
            glm::vec3 mirror(-wo.x, -wo.y, wo.z);
            double fresnel = fresnelReference(std::abs(wo.z), material.ior);
            // (Principled: the mirror direction; its share is the delta bin's count.)
            bool good = hasDelta && glm::length(sample.wiLocal - mirror) < 1e-6f &&
                        (principled || std::abs(sample.pdfSolidAngle - deltaProbability) < 1e-5) &&
                        (principled ||
                        std::abs(sample.weight.x - fresnel / deltaProbability) < 1e-4 * fresnel / deltaProbability);
            if (!good && ++badDelta <= 3)
                ADD_FAILURE() << "delta sample: wi (" << sample.wiLocal.x << ", " << sample.wiLocal.y << ", "
                              << sample.wiLocal.z << "), pdf " << sample.pdfSolidAngle << " (coat probability "
                              << deltaProbability << "), weight " << sample.weight.x;
        } else {
            int bin = binning.binOf(glm::dvec3(sample.wiLocal));
            if (bin < 0)
                ++outside;
            else
                observed[std::size_t(bin)] += 1.0;
        }
    }

    std::vector<double> expected = integrateBins(material, wo, binning, 8, pdfIntegrand);
    double integral = 0.0;
    for (double& count : expected) {
        integral += count;
        count *= kChiSquareSamples;
    }
    // A failure share down to 1e-6 is float rounding at the hemisphere's edge (a cosine sample
    // with z rounded to 0), not a model that loses samples.
    expected.push_back(std::max(1.0 - integral - deltaProbability, 1e-6) * kChiSquareSamples);
    expected.push_back(deltaProbability * kChiSquareSamples);

    ChiSquareResult result = testing::chiSquareTest(observed, expected);
    const double significance = testing::sidakSignificance(kSignificance, int(lobeCases().size()));
    std::printf("  %-40s %s; integral of pdf %.6f, failed %.0f, delta %.0f\n", lobe.label.c_str(),
                testing::describe(result).c_str(), integral, observed[failedBin], observed[deltaBin]);
    EXPECT_EQ(outside, 0) << "non-delta samples outside the chart";
    EXPECT_EQ(badDelta, 0);
    EXPECT_LE(integral + deltaProbability, 1.0 + 1e-3) << "the pdf integrates to more than 1";
    EXPECT_GT(result.pValue, significance)
        << lobe.label << ": " << testing::describe(result) << ", significance " << significance << "\n"
        << testing::worstBinsTable(observed, expected, [&](std::size_t bin) { return binning.label(bin); });
}

// ---- 2. A sample's pdf and weight agree with bsdfPdf and bsdfF re-evaluated at its wi

// Tolerances. weight vs f |cos| / pdf at wi: the GGX D cancels between f and pdf evaluated at the
// same wi, so only a few float roundings separate them: 1e-4 relative. pdf vs bsdfPdf(wi): the
// same 1e-4 plus the conditioning of the pdf itself. The sample's pdf belongs to the exact
// reflection of wo about the sampled h, bsdfPdf to that wi rounded to float, and the GPU forms
// h = normalize(wo + wi): when wo + wi nearly cancel (grazing incidence, |wo + wi| = 2 wo.h =
// 0.04 at cos 0.02) half an ulp in wi's x or y -- in its direction or just its length -- turns
// h by ~1.5e-6 rad, and a lobe of width alpha = 1e-3 changes its density by up to ~2/alpha per
// radian of h: ~3e-3. ggxPdfRoundingBound computes that first-order effect per sample from a
// double-precision reference; the pdfs must agree to twice it (the worst case observed is 1x).
constexpr double kWeightTolerance = 1e-4;
constexpr double kPdfTolerance = 1e-4;
constexpr double kConditioning = 2.0;
constexpr int kConsistencySamples = 200000;

TEST_P(BsdfLobe, SamplesAgreeWithEvaluation) {
    const LobeCase& lobe = GetParam();
    const Material& material = lobe.material;
    const glm::vec3 wo = directionAt(lobe.cosThetaO);
    const bool ggx = material.type == MaterialType::Metal && !isSmooth(material.roughness);
    // The principled mixture's pdf is as ill-conditioned as its GGX part at most.
    const bool ggxBound = (ggx || material.type == MaterialType::Principled) && !isSmooth(material.roughness);
    const double alpha = ggxAlpha(material.roughness);

    int checked = 0, failedBadly = 0, beyond1e3 = 0, bad = 0;
    double worstWeight = 0.0, worstPdf = 0.0, worstPdfOverTolerance = 0.0, worstReference = 0.0;
    for (const BsdfProbeSample& sample : probe().sample(material, {wo}, kConsistencySamples, lobe.seed + 500u)) {
        if (sample.pdfSolidAngle == 0.0f) {
            failedBadly += sample.weight == glm::vec3(0.0f) ? 0 : 1;
            continue;
        }
        if (sample.isDelta) continue;
        ++checked;
        double pdf = sample.pdfSolidAngle, pdfAtWi = sample.pdfAtWi;
        double pdfError = std::abs(pdf - pdfAtWi) / pdf;
        double pdfTolerance = kPdfTolerance;
        if (ggxBound) pdfTolerance += kConditioning * ggxPdfRoundingBound(glm::dvec3(wo), sample.wiLocal, alpha);
        if (ggx) {
            // The re-evaluation itself is accurate: it matches double precision at the float wi.
            double reference = ggxReflectionPdfReference(glm::dvec3(wo), glm::dvec3(sample.wiLocal), alpha);
            worstReference = std::max(worstReference, std::abs(pdfAtWi - reference) / reference);
        }
        beyond1e3 += pdfError > 1e-3 ? 1 : 0;
        worstPdf = std::max(worstPdf, pdfError);
        worstPdfOverTolerance = std::max(worstPdfOverTolerance, pdfError / pdfTolerance);

        double cosThetaI = std::abs(double(sample.wiLocal.z));
        double weightError = 0.0;
        for (int c = 0; c < 3; ++c) {
            double expected = double(sample.fAtWi[c]) * cosThetaI / pdfAtWi;
            double scale = std::max(std::abs(expected), 1e-3 * double(material.color[c]) + 1e-12);
            weightError = std::max(weightError, std::abs(double(sample.weight[c]) - expected) / scale);
        }
        worstWeight = std::max(worstWeight, weightError);
        bool good = std::isfinite(pdfError) && pdfError <= pdfTolerance && weightError <= kWeightTolerance;
        if (!good && ++bad <= 3)
            ADD_FAILURE() << "wi (" << sample.wiLocal.x << ", " << sample.wiLocal.y << ", " << sample.wiLocal.z
                          << "): pdf " << pdf << " vs " << pdfAtWi << " at wi (relative " << pdfError
                          << ", tolerance " << pdfTolerance << "); weight (" << sample.weight.x << ", "
                          << sample.weight.y << ", " << sample.weight.z << ") vs f|cos|/pdf relative " << weightError;
    }
    std::printf("  %-40s %d samples: worst relative pdf difference %.3g (%.3g of its tolerance, %.2f%% > 1e-3), "
                "weight %.3g; pdfAtWi vs double %.3g\n",
                lobe.label.c_str(), checked, worstPdf, worstPdfOverTolerance, 100.0 * beyond1e3 / std::max(checked, 1),
                worstWeight, worstReference);
    EXPECT_GT(checked, 1000);
    EXPECT_EQ(failedBadly, 0) << "samples with pdf 0 but a nonzero weight";
    EXPECT_EQ(bad, 0);
    if (ggx) { EXPECT_LT(worstReference, 1e-4) << "bsdfPdf of the metal strays from its double-precision value"; }
}

INSTANTIATE_TEST_SUITE_P(SampledModels, BsdfLobe, ::testing::ValuesIn(lobeCases()),
                         [](const ::testing::TestParamInfo<LobeCase>& info) { return info.param.label; });

// Right at the smooth threshold alpha = 1e-3: roughness 0.0316 (alpha 0.000999) is a delta
// mirror, 0.0317 (alpha 0.001005) a GGX lobe; roughness sqrt(0.001) itself is reported.
TEST(Bsdf, SmoothThresholdIsAlphaOneThousandth) {
    const glm::vec3 wo = directionAt(0.7);
    auto deltaShare = [&](MaterialType type, float roughness) {
        int delta = 0, total = 0;
        for (const BsdfProbeSample& sample : probe().sample(makeMaterial(type, roughness), {wo}, 20000, 3u)) {
            if (sample.pdfSolidAngle == 0.0f) continue;
            ++total;
            delta += sample.isDelta ? 1 : 0;
        }
        return double(delta) / std::max(total, 1);
    };
    const float threshold = std::sqrt(0.001f);
    std::printf("  roughness sqrt(0.001) = %.9g, squared in float = %.9g: metal %s\n", double(threshold),
                double(threshold * threshold), deltaShare(MaterialType::Metal, threshold) == 1.0 ? "smooth (delta)" : "rough");
    EXPECT_EQ(deltaShare(MaterialType::Metal, 0.0316f), 1.0);
    EXPECT_EQ(deltaShare(MaterialType::Metal, 0.0317f), 0.0);
    EXPECT_GT(deltaShare(MaterialType::Plastic, 0.0316f), 0.0); // the smooth coat's mirror lobe
    EXPECT_EQ(deltaShare(MaterialType::Plastic, 0.0317f), 0.0);
    // The smooth metal is a Schlick-weighted mirror.
    Material metal = makeMaterial(MaterialType::Metal, 0.0316f, 1.5f, {0.9f, 0.6f, 0.3f});
    for (const BsdfProbeSample& sample : probe().sample(metal, {wo}, 16, 4u)) {
        EXPECT_FLOAT_EQ(sample.pdfSolidAngle, 1.0f);
        EXPECT_EQ(sample.wiLocal, glm::vec3(-wo.x, -wo.y, wo.z));
        double m = std::pow(1.0 - double(wo.z), 5.0);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(sample.weight[c], metal.color[c] + (1.0 - metal.color[c]) * m, 1e-5) << "channel " << c;
    }
}

// ---- 3. White furnace

struct FurnaceCase {
    Material material;
    std::string label;
};

void PrintTo(const FurnaceCase& furnace, std::ostream* out) { *out << furnace.label; }

const std::vector<double> kFurnaceCosines = {0.999, 0.7, 0.5, 0.3, 0.02, -0.02, -0.3, -0.5, -0.7, -0.999};
const std::vector<float> kFurnaceRoughness = {0.0f, 0.05f, 0.3f, 1.0f};
const std::vector<float> kFurnaceIors = {1.0f, 1.33f, 1.5f, 3.0f};

// Every model at colour 1, roughness and ior where the model has them.
const std::vector<FurnaceCase>& furnaceCases() {
    static const std::vector<FurnaceCase> cases = [] {
        std::vector<Material> materials = {makeMaterial(MaterialType::Diffuse), makeMaterial(MaterialType::DiffuseTransmission),
                                           makeMaterial(MaterialType::Mirror)};
        for (float ior : kFurnaceIors) materials.push_back(makeMaterial(MaterialType::SpecularTransmission, 0.0f, ior));
        for (float ior : kFurnaceIors) materials.push_back(makeMaterial(MaterialType::Glass, 0.0f, ior));
        for (float roughness : kFurnaceRoughness) materials.push_back(makeMaterial(MaterialType::Metal, roughness));
        for (float roughness : kFurnaceRoughness)
            for (float ior : kFurnaceIors) materials.push_back(makeMaterial(MaterialType::Plastic, roughness, ior));
        for (float roughness : kFurnaceRoughness)
            for (float metallic : {0.0f, 0.5f, 1.0f}) materials.push_back(makePrincipled(metallic, roughness));
        for (float transmission : {0.5f, 1.0f}) materials.push_back(makePrincipled(0.0f, 0.3f, glm::vec3(1.0f), transmission));
        std::vector<FurnaceCase> list;
        for (const Material& material : materials) {
            char label[96];
            std::snprintf(label, sizeof label, "%s_r%g_ior%g", typeLabel(material).c_str(), double(material.roughness),
                          double(material.ior));
            list.push_back({material, testName(label)});
        }
        return list;
    }();
    return cases;
}

// Whether the model loses no energy at this incidence: it must then reflect and transmit all
// of it (colour 1).
bool isLossless(const Material& material, double cosThetaO) {
    switch (material.type) {
    case MaterialType::Diffuse:
    case MaterialType::DiffuseTransmission:
    case MaterialType::Mirror:
    case MaterialType::Glass: return true;
    case MaterialType::SpecularTransmission: // loses what total internal reflection would return
        return cosThetaO > 0.0 || std::sqrt(1.0 - cosThetaO * cosThetaO) * material.ior < 1.0;
    case MaterialType::Metal: return isSmooth(material.roughness); // Schlick(1) = 1: a perfect mirror
    case MaterialType::Plastic: return material.ior == 1.0f;       // no coat: the white Lambertian base
    // Principled: lossless where its parts are: the smooth white metal, and pure glass.
    case MaterialType::Principled:
        return (material.metallic == 1.0f && isSmooth(material.roughness)) ||
               (material.metallic == 0.0f && material.transmission == 1.0f);
    case MaterialType::Medium: return true; // a volume's boundary: light passes it unchanged
    case MaterialType::Emitter: return false;
    }
    return false;
}

struct Estimate {
    double mean = 0.0;
    double standardError = 0.0;
};

Estimate meanOf(double sum, double sumSquares, int n) {
    double mean = sum / n;
    double variance = std::max(0.0, sumSquares / n - mean * mean) * n / std::max(n - 1, 1);
    return {mean, std::sqrt(variance / n)};
}

class BsdfFurnace : public ::testing::TestWithParam<FurnaceCase> {};

// The directional albedo a(wo) = integral of f |cos| d wi (delta lobes included) is E[weight].
// It must not exceed 1 beyond 3 standard errors (+1e-5 for float rounding: a white Lambertian's
// weights are all 1 give or take an ulp, and its standard error is then ~0); the lossless
// models must reach 1 within 1%. The non-delta part of the albedo, E[weight of non-delta
// samples], must match a quadrature of f |cos| with bsdfF over a fine grid of the model's chart
// (256 x 64 points: (z, phi) for the Lambertian lobes, where the midpoint rule is exact in z; the
// half-vector chart for GGX lobes, which a (z, phi) grid cannot resolve at alpha = 0.0025) within
// 4 standard errors + 2e-3 for the grid.
TEST_P(BsdfFurnace, AlbedoIsAtMostOne) {
    const Material& material = GetParam().material;
    std::vector<glm::vec3> wos;
    for (double cosThetaO : kFurnaceCosines) wos.push_back(directionAt(cosThetaO));
    const int count = kFurnaceSamples * int(wos.size());
    std::vector<BsdfProbeSample> samples = probe().sample(material, wos, count, 11u);

    const bool hasNonDeltaPart = material.type == MaterialType::Diffuse ||
                                 material.type == MaterialType::DiffuseTransmission ||
                                 (material.type == MaterialType::Metal && !isSmooth(material.roughness)) ||
                                 material.type == MaterialType::Plastic ||
                                 (material.type == MaterialType::Principled &&
                                  !(isSmooth(material.roughness) && material.metallic == 1.0f) && material.transmission < 1.0f);
    for (std::size_t k = 0; k < wos.size(); ++k) {
        const double cosThetaO = kFurnaceCosines[k];
        double sum = 0.0, sumSquares = 0.0, sumNonDelta = 0.0, sumNonDeltaSquares = 0.0;
        for (std::size_t i = k; i < samples.size(); i += wos.size()) {
            double weight = channelMean(samples[i].weight);
            sum += weight;
            sumSquares += weight * weight;
            if (!samples[i].isDelta) {
                sumNonDelta += weight;
                sumNonDeltaSquares += weight * weight;
            }
        }
        const Estimate albedo = meanOf(sum, sumSquares, kFurnaceSamples);
        const Estimate nonDelta = meanOf(sumNonDelta, sumNonDeltaSquares, kFurnaceSamples);
        double quadrature = std::nan("");
        if (hasNonDeltaPart) {
            SphereChart sphere;
            HalfVectorChart halfVector(wos[k], ggxAlpha(material.roughness));
            const Binning grid{usesHalfVectorChart(material) ? static_cast<const Chart*>(&halfVector) : &sphere, 64, 16};
            double total = 0.0;
            for (double bin : integrateBins(material, wos[k], grid, 4, projectedFIntegrand)) total += bin;
            quadrature = total;
        }
        std::printf("  %-30s %-8s albedo %.7f +- %.2g; non-delta %.7f +- %.2g, quadrature %.7f\n",
                    GetParam().label.c_str(), cosLabel(cosThetaO).c_str(), albedo.mean, albedo.standardError,
                    nonDelta.mean, nonDelta.standardError, quadrature);
        EXPECT_LE(albedo.mean, 1.0 + 3.0 * albedo.standardError + 1e-5)
            << "energy gain at cos(theta_o) = " << cosThetaO << ": albedo " << albedo.mean << " +- "
            << albedo.standardError;
        if (isLossless(material, cosThetaO)) {
            EXPECT_NEAR(albedo.mean, 1.0, 0.01) << "lossless model at cos(theta_o) = " << cosThetaO;
        }
        if (hasNonDeltaPart) {
            EXPECT_NEAR(nonDelta.mean, quadrature, 4.0 * nonDelta.standardError + 2e-3)
                << "Monte Carlo and quadrature disagree at cos(theta_o) = " << cosThetaO;
        }
    }
}

INSTANTIATE_TEST_SUITE_P(AllModels, BsdfFurnace, ::testing::ValuesIn(furnaceCases()),
                         [](const ::testing::TestParamInfo<FurnaceCase>& info) { return info.param.label; });

// ---- 4. Glass: Fresnel choice and Snell's law

const std::vector<double> kGlassCosines = {0.999, 0.7, 0.3, 0.02, -0.999, -0.95, -0.9, -0.7, -0.5, -0.3, -0.02};

// eta_o sin(theta_o) = eta_i sin(theta_i), and wi in the plane of incidence opposite wo.
void expectSnell(const Material& material, glm::vec3 wo, const BsdfProbeSample& sample, int& bad) {
    double etaO = wo.z > 0.0f ? 1.0 : material.ior, etaI = wo.z > 0.0f ? material.ior : 1.0;
    glm::dvec3 o(wo), i(sample.wiLocal);
    double sinO = std::hypot(o.x, o.y) / glm::length(o), sinI = std::hypot(i.x, i.y) / glm::length(i);
    double snell = std::abs(etaO * sinO - etaI * sinI);
    double offPlane = std::abs(o.x * i.y - o.y * i.x); // |(o x i).z|: 0 in the plane of incidence
    bool good = o.z * i.z < 0.0 && snell <= 1e-5 && offPlane <= 1e-5 && o.x * i.x + o.y * i.y <= 0.0 &&
                std::abs(glm::length(i) - 1.0) <= 1e-5;
    if (!good && ++bad <= 3)
        ADD_FAILURE() << material.name << " ior " << material.ior << ", wo.z " << wo.z << ": refracted wi (" << i.x
                      << ", " << i.y << ", " << i.z << "), |eta_o sin_o - eta_i sin_i| = " << snell
                      << ", off the plane of incidence by " << offPlane;
}

TEST(Bsdf, GlassReflectsWithFresnelProbabilityAndRefractsBySnell) {
    constexpr int kPerDirection = 100000;
    for (float ior : kFurnaceIors) {
        Material glass = makeMaterial(MaterialType::Glass, 0.0f, ior);
        std::vector<glm::vec3> wos;
        for (double cosThetaO : kGlassCosines) wos.push_back(directionAt(cosThetaO));
        std::vector<BsdfProbeSample> samples =
            probe().sample(glass, wos, kPerDirection * int(wos.size()), 21u + std::uint32_t(ior * 100.0f));
        for (std::size_t k = 0; k < wos.size(); ++k) {
            const glm::vec3 wo = wos[k];
            const double fresnel = fresnelReference(wo.z, ior);
            int reflected = 0, bad = 0;
            for (std::size_t n = k; n < samples.size(); n += wos.size()) {
                const BsdfProbeSample& sample = samples[n];
                if ((!sample.isDelta || sample.weight != glm::vec3(1.0f)) && ++bad <= 3)
                    ADD_FAILURE() << "glass sample: isDelta " << sample.isDelta << ", weight (" << sample.weight.x << ", "
                                  << sample.weight.y << ", " << sample.weight.z << "), tint 1";
                if (sample.wiLocal.z * wo.z > 0.0f) {
                    ++reflected;
                    if ((sample.wiLocal != glm::vec3(-wo.x, -wo.y, wo.z) || std::abs(sample.pdfSolidAngle - fresnel) > 2e-5) &&
                        ++bad <= 3)
                        ADD_FAILURE() << "reflection: wi (" << sample.wiLocal.x << ", " << sample.wiLocal.y << ", "
                                      << sample.wiLocal.z << "), pdf " << sample.pdfSolidAngle << ", Fresnel " << fresnel;
                } else {
                    if (std::abs(sample.pdfSolidAngle - (1.0 - fresnel)) > 2e-5 && ++bad <= 3)
                        ADD_FAILURE() << "refraction pdf " << sample.pdfSolidAngle << ", 1 - Fresnel " << 1.0 - fresnel;
                    expectSnell(glass, wo, sample, bad);
                }
            }
            // Binomial: 5 standard deviations (with 44 such checks, a chance of ~3e-5 of a false alarm).
            const double expected = fresnel * kPerDirection;
            const double sigma = std::sqrt(kPerDirection * fresnel * (1.0 - fresnel));
            std::printf("  glass ior %-4g cos %-6g reflected %6d of %d, expected %.1f +- %.1f (Fresnel %.6f)\n",
                        double(ior), double(wo.z), reflected, kPerDirection, expected, sigma, fresnel);
            EXPECT_NEAR(reflected, expected, 5.0 * sigma + 1e-9)
                << "ior " << ior << ", cos(theta_o) " << wo.z << ": reflected share " << double(reflected) / kPerDirection
                << " vs Fresnel " << fresnel;
            EXPECT_EQ(bad, 0);
        }
    }
}

TEST(Bsdf, SpecularTransmissionRefractsBySnellOrFails) {
    for (float ior : kFurnaceIors) {
        Material material = makeMaterial(MaterialType::SpecularTransmission, 0.0f, ior);
        std::vector<glm::vec3> wos;
        for (double cosThetaO : kGlassCosines) wos.push_back(directionAt(cosThetaO));
        int bad = 0;
        std::vector<BsdfProbeSample> samples = probe().sample(material, wos, 64 * int(wos.size()), 5u);
        for (std::size_t n = 0; n < samples.size(); ++n) {
            const glm::vec3 wo = wos[n % wos.size()];
            const BsdfProbeSample& sample = samples[n];
            bool totalInternalReflection = fresnelReference(wo.z, ior) == 1.0;
            if (totalInternalReflection) {
                EXPECT_EQ(sample.pdfSolidAngle, 0.0f) << "cos " << wo.z << " ior " << ior;
                EXPECT_EQ(sample.weight, glm::vec3(0.0f));
            } else {
                EXPECT_TRUE(sample.isDelta);
                EXPECT_EQ(sample.pdfSolidAngle, 1.0f);
                EXPECT_EQ(sample.weight, glm::vec3(1.0f));
                expectSnell(material, wo, sample, bad);
            }
        }
        EXPECT_EQ(bad, 0);
    }
}

// ---- 5. Reciprocity

struct ReciprocityCase {
    Material material;
    std::string label;
};

void PrintTo(const ReciprocityCase& test, std::ostream* out) { *out << test.label; }

const std::vector<ReciprocityCase>& reciprocityCases() {
    static const std::vector<ReciprocityCase> cases = [] {
        std::vector<Material> materials = {makeMaterial(MaterialType::Diffuse, 0.0f, 1.5f, {0.8f, 0.6f, 0.4f}),
                                           makeMaterial(MaterialType::DiffuseTransmission, 0.0f, 1.5f, {0.8f, 0.6f, 0.4f})};
        for (float roughness : kRoughRoughness)
            materials.push_back(makeMaterial(MaterialType::Metal, roughness, 1.5f, {0.9f, 0.6f, 0.3f}));
        for (float ior : {1.33f, 1.5f, 3.0f}) {
            materials.push_back(makeMaterial(MaterialType::Plastic, 0.0f, ior, {0.7f, 0.5f, 0.3f}));
            for (float roughness : kRoughRoughness)
                materials.push_back(makeMaterial(MaterialType::Plastic, roughness, ior, {0.7f, 0.5f, 0.3f}));
        }
        for (float metallic : {0.0f, 0.5f, 1.0f})
            for (float roughness : {0.0317f, 0.5477226f, 1.0f})
                materials.push_back(makePrincipled(metallic, roughness, {0.8f, 0.5f, 0.3f}));
        std::vector<ReciprocityCase> list;
        for (const Material& material : materials) {
            char label[96];
            std::snprintf(label, sizeof label, "%s_r%g_ior%g", typeLabel(material).c_str(), double(material.roughness),
                          double(material.ior));
            list.push_back({material, testName(label)});
        }
        return list;
    }();
    return cases;
}

class BsdfReciprocity : public ::testing::TestWithParam<ReciprocityCase> {};

// f(wo, wi) == f(wi, wo) to 1e-4 relative per channel, over 100000 pairs: half uniform on the
// sphere, half near the specular configuration (half vector within a few alpha of the normal,
// where a GGX f is large). A pair lies on one side for the reflection models and on opposite
// sides for the Lambertian transmission, with wo on the front or the back at random.
// Pairs where f lies outside [1e-6, 1e7] are skipped as beyond what float tells apart (a value
// of 1e-6 is nothing next to the lobe; above 1e7 the spike is narrower than float's resolution
// of directions) and reported.
// The half vector of a nearly opposite pair, (wo + wi) / |wo + wi|, is ill-conditioned: float
// rounding turns it by about FLT_EPSILON / |wo + wi| radians, and D changes by a few times that
// relative per radian at moderate roughness. Such pairs (both grazing, on opposite azimuths) get
// that much more slack, 8 FLT_EPSILON / |wo + wi|; at |wo + wi| = 0.005 the tolerance is 3e-4.
TEST_P(BsdfReciprocity, FIsSymmetric) {
    const Material& material = GetParam().material;
    const bool transmission = material.type == MaterialType::DiffuseTransmission;
    const double alpha = std::max(ggxAlpha(material.roughness), 1e-3);
    std::mt19937 random(1234u);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    std::normal_distribution<double> normal(0.0, 1.0);
    auto uniformUpper = [&]() {
        double z = uniform(random), phi = kTwoPi * uniform(random), r = std::sqrt(std::max(0.0, 1.0 - z * z));
        return glm::dvec3(r * std::cos(phi), r * std::sin(phi), z);
    };
    constexpr int kPairs = 100000;
    std::vector<glm::vec3> wos, wis;
    while (int(wos.size()) < kPairs) {
        glm::dvec3 wo = uniformUpper(), wi;
        if (wos.size() % 2 == 0) {
            wi = uniformUpper();
        } else {
            // Braces, not parentheses: a braced list is evaluated left to right, a call's arguments in an
            // unspecified order (GCC and clang differ), and the draws must be the same on every compiler.
            glm::dvec3 h = glm::normalize(glm::dvec3{2.0 * alpha * normal(random), 2.0 * alpha * normal(random), 1.0});
            wi = 2.0 * glm::dot(wo, h) * h - wo;
            if (wi.z <= 0.0) continue;
        }
        bool back = uniform(random) < 0.5;
        if (back) wo.z = -wo.z;
        if (back != transmission) wi.z = -wi.z;
        wos.push_back(glm::vec3(wo));
        wis.push_back(glm::vec3(wi));
    }
    std::vector<BsdfProbeValue> forward = probe().evaluate(material, wos, wis);
    std::vector<BsdfProbeValue> backward = probe().evaluate(material, wis, wos);
    int compared = 0, tiny = 0, huge = 0, bad = 0;
    double worst = 0.0;
    std::size_t worstPair = 0;
    for (std::size_t n = 0; n < wos.size(); ++n) {
        for (int c = 0; c < 3; ++c) {
            double a = forward[n].f[c], b = backward[n].f[c];
            double largest = std::max(std::abs(a), std::abs(b));
            if (largest < 1e-6) {
                ++tiny;
                continue;
            }
            if (largest > 1e7) {
                ++huge;
                continue;
            }
            ++compared;
            double error = std::abs(a - b) / largest;
            if (error > worst) {
                worst = error;
                worstPair = n;
            }
            const double tolerance = 1e-4 + 8.0 * FLT_EPSILON / std::max(1e-3, double(glm::length(wos[n] + wis[n])));
            if (error > tolerance && ++bad <= 3)
                ADD_FAILURE() << "wo (" << wos[n].x << ", " << wos[n].y << ", " << wos[n].z << "), wi (" << wis[n].x << ", "
                              << wis[n].y << ", " << wis[n].z << "): f " << a << " but reversed " << b;
        }
    }
    const glm::vec3 o = wos[worstPair], i = wis[worstPair];
    std::printf("  %-30s %d values compared, worst relative difference %.3g (wo.z %.3g, wi.z %.3g, |wo + wi| %.3g); "
                "skipped %d tiny, %d huge\n",
                GetParam().label.c_str(), compared, worst, double(o.z), double(i.z), double(glm::length(o + i)), tiny, huge);
    EXPECT_GT(compared, kPairs);
    EXPECT_EQ(bad, 0);
}

INSTANTIATE_TEST_SUITE_P(ReflectionModels, BsdfReciprocity, ::testing::ValuesIn(reciprocityCases()),
                         [](const ::testing::TestParamInfo<ReciprocityCase>& info) { return info.param.label; });

// ---- 6. No NaN or Inf

// All 8 material types over the corner cases of their parameters; wo from straight below to
// straight above, exactly in the surface, and 1e-6 off it. Sampling: every value finite, pdf and
// weight >= 0, wi of unit length unless the sample failed (pdf 0, and then weight 0). Evaluation
// for every (wo, wi) pair of those directions plus each wo's mirror and opposite: f and pdf
// finite and >= 0.
TEST(Bsdf, NoNanOrInfForAnyMaterialOrDirection) {
    std::vector<Material> materials;
    const std::vector<float> roughnesses = {0.0f, 1e-4f, 0.01f, 0.0316f, 0.0317f, 0.05f, 0.3f, 0.7f, 1.0f};
    const std::vector<float> iors = {1.0f, 1.0001f, 1.33f, 1.5f, 3.0f};
    for (glm::vec3 color : {glm::vec3(0.0f), glm::vec3(1.0f)}) {
        for (MaterialType type : {MaterialType::Diffuse, MaterialType::Emitter, MaterialType::DiffuseTransmission,
                                  MaterialType::Mirror})
            materials.push_back(makeMaterial(type, 0.0f, 1.5f, color));
        for (float ior : iors) {
            materials.push_back(makeMaterial(MaterialType::SpecularTransmission, 0.0f, ior, color));
            materials.push_back(makeMaterial(MaterialType::Glass, 0.0f, ior, color));
        }
        for (float roughness : roughnesses) {
            materials.push_back(makeMaterial(MaterialType::Metal, roughness, 1.5f, color));
            for (float ior : iors) materials.push_back(makeMaterial(MaterialType::Plastic, roughness, ior, color));
            for (float metallic : {0.0f, 0.5f, 1.0f})
                for (float transmission : {0.0f, 0.5f}) materials.push_back(makePrincipled(metallic, roughness, color, transmission));
        }
    }
    std::vector<glm::vec3> directions;
    for (double cosTheta : {-1.0, -0.9999, -0.7, -0.3, -0.02, -1e-3, -1e-6, 0.0, 1e-6, 1e-3, 0.02, 0.3, 0.7, 0.9999, 1.0})
        for (double phi : {0.0, kWoAzimuth, 2.5}) directions.push_back(directionAt(cosTheta, phi));
    std::vector<glm::vec3> pairWo, pairWi;
    for (glm::vec3 wo : directions) {
        std::vector<glm::vec3> wis = directions;
        wis.push_back(glm::vec3(-wo.x, -wo.y, wo.z)); // the mirror direction: h = the normal
        wis.push_back(-wo);                           // wo + wi = 0: no half vector
        for (glm::vec3 wi : wis) {
            pairWo.push_back(wo);
            pairWi.push_back(wi);
        }
    }
    constexpr int kSamplesPerDirection = 512;
    int bad = 0, samplesChecked = 0, failed = 0;
    auto finite = [](glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (const Material& material : materials) {
        std::vector<BsdfProbeSample> samples =
            probe().sample(material, directions, kSamplesPerDirection * int(directions.size()), 99u);
        for (std::size_t n = 0; n < samples.size(); ++n) {
            const BsdfProbeSample& s = samples[n];
            const bool fail = s.pdfSolidAngle == 0.0f;
            bool good = finite(s.wiLocal) && finite(s.weight) && finite(s.fAtWi) && std::isfinite(s.pdfSolidAngle) &&
                        std::isfinite(s.pdfAtWi) && s.pdfSolidAngle >= 0.0f && s.pdfAtWi >= 0.0f &&
                        glm::all(glm::greaterThanEqual(s.weight, glm::vec3(0.0f))) &&
                        glm::all(glm::greaterThanEqual(s.fAtWi, glm::vec3(0.0f))) &&
                        (fail ? s.weight == glm::vec3(0.0f) : std::abs(glm::length(s.wiLocal) - 1.0f) <= 1e-5f);
            if (material.type == MaterialType::Emitter) good = good && fail;
            ++samplesChecked;
            failed += fail ? 1 : 0;
            glm::vec3 wo = directions[n % directions.size()];
            if (!good && ++bad <= 10)
                ADD_FAILURE() << material.name << " roughness " << material.roughness << " ior " << material.ior
                              << " colour " << material.color.x << ", wo (" << wo.x << ", " << wo.y << ", " << wo.z
                              << "): wi (" << s.wiLocal.x << ", " << s.wiLocal.y << ", " << s.wiLocal.z << "), pdf "
                              << s.pdfSolidAngle << ", weight (" << s.weight.x << ", " << s.weight.y << ", "
                              << s.weight.z << "), f at wi " << s.fAtWi.x << ", pdf at wi " << s.pdfAtWi;
        }
        std::vector<BsdfProbeValue> values = probe().evaluate(material, pairWo, pairWi);
        for (std::size_t n = 0; n < values.size(); ++n) {
            const BsdfProbeValue& v = values[n];
            bool good = finite(v.f) && std::isfinite(v.pdfSolidAngle) && v.pdfSolidAngle >= 0.0f &&
                        glm::all(glm::greaterThanEqual(v.f, glm::vec3(0.0f)));
            if (!good && ++bad <= 10)
                ADD_FAILURE() << material.name << " roughness " << material.roughness << " ior " << material.ior
                              << ": f(wo (" << pairWo[n].x << ", " << pairWo[n].y << ", " << pairWo[n].z << "), wi ("
                              << pairWi[n].x << ", " << pairWi[n].y << ", " << pairWi[n].z << ")) = (" << v.f.x << ", "
                              << v.f.y << ", " << v.f.z << "), pdf " << v.pdfSolidAngle;
        }
    }
    std::printf("  %zu materials, %d samples (%d failed cleanly), %zu evaluations each\n", materials.size(),
                samplesChecked, failed, pairWo.size());
    EXPECT_EQ(bad, 0);
}

} // namespace
} // namespace ptview
