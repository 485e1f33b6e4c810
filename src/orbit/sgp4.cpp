// SGP4/SDP4 (sgp4.hpp). Each step names the routine of the reference code of [V06] (Vallado,
// Crawford, Hujsak & Kelso 2006, sgp4unit) that it follows, and keeps its variable names and
// the order of its operations (so that the results agree with the reference's to rounding:
// tcppver.out is reproduced to 2e-7 km). Where [V06] corrected Spacetrack Report #3 [STR3] the
// comment says "sgp4fix", as the reference does. Lines that the reference computes but never
// uses are left out and said so.
#include "orbit/sgp4.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "conescan/enum_names.hpp"
namespace conescan::orbit {
namespace {

using sgp4_detail::deep_space_terms;
using sgp4_detail::near_earth_terms;
using sgp4_detail::resonance_node;
using sgp4_detail::third_body_periodics;

constexpr double pi = std::numbers::pi;
constexpr double twopi = 2.0 * pi;
constexpr double deg2rad = pi / 180.0;
constexpr double x2o3 = 2.0 / 3.0;
constexpr double temp4 = 1.5e-12;  // sgp4fix: the divisor 1 + cos i where i = 180 deg
constexpr double rptim = 4.37526908801129966e-3;  // Earth's rotation, rad/min (dsinit, dspace)
constexpr double jd_1950 = 2433281.5;             // JD of 1949 December 31, 0 h (SGP4's origin)

/// WGS-72, the constants the element sets are fitted with ([V06] getgravconst "wgs72").
struct gravity {
  double mu = 398600.8;  // km^3/s^2
  double radiusearthkm = 6378.135;
  double xke = 60.0 / std::sqrt(radiusearthkm * radiusearthkm * radiusearthkm / mu);  // er^1.5/min
  double j2 = 0.001082616, j3 = -0.00000253881, j4 = -0.00000165597;
  double j3oj2 = j3 / j2;
};

const gravity& wgs72() {
  static const gravity constants{};
  return constants;
}

double not_a_number() {
  return std::numeric_limits<double>::quiet_NaN();
}

teme_state failed(sgp4_status status) {
  const vec3<double> nan(not_a_number());
  return {nan, nan, status};
}

// ---- sgp4init: the model at epoch --------------------------------------------------------

/// Greenwich mean sidereal time at a UT1 Julian date, IAU-82 ([V06] gstime, Vallado 2013
/// eq. 3-45), rad in [0, 2 pi): the improved mode's sidereal time at epoch.
double gstime(double jdut1) {
  const double tut1 = (jdut1 - 2451545.0) / 36525.0;
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600 + 8640184.812866) * tut1 + 67310.54841;  // s
  temp = std::fmod(temp * deg2rad / 240.0, twopi);  // 360 deg / 86400 s = 1 / 240
  return temp < 0.0 ? temp + twopi : temp;
}

/// The AFSPC code's sidereal time at epoch, from 1970 January 0 ([V06] initl, opsmode 'a').
double gstime_afspc(double epoch) {
  const double ts70 = epoch - 7305.0;
  const double ds70 = std::floor(ts70 + 1.0e-8);
  const double tfrac = ts70 - ds70;
  const double c1 = 1.72027916940703639e-2;
  const double thgr70 = 1.7321343856509374;
  const double fk5r = 5.07551419432269442e-15;
  const double c1p2p = c1 + twopi;
  const double gsto = std::fmod(thgr70 + c1 * ds70 + c1p2p * tfrac + ts70 * ts70 * fk5r, twopi);
  return gsto < 0.0 ? gsto + twopi : gsto;
}

/// initl: quantities at epoch, and the Brouwer mean motion n0'' recovered from the TLE's Kozai
/// mean motion ([STR3] §6: a1, delta1, a0, delta0, n0'').
struct epoch_quantities {
  double no_unkozai, ao, con41, con42, cosio, cosio2, eccsq, omeosq, posq, rp, rteosq, sinio;
};

epoch_quantities initl(const sgp4_elements& el) {
  const gravity& g = wgs72();
  epoch_quantities q{};
  q.eccsq = el.eccentricity * el.eccentricity;
  q.omeosq = 1.0 - q.eccsq;
  q.rteosq = std::sqrt(q.omeosq);
  q.cosio = std::cos(el.inclination_rad);
  q.cosio2 = q.cosio * q.cosio;
  const double ak = std::pow(g.xke / el.mean_motion_rad_min, x2o3);
  const double d1 = 0.75 * g.j2 * (3.0 * q.cosio2 - 1.0) / (q.rteosq * q.omeosq);
  double del = d1 / (ak * ak);
  const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
  del = d1 / (adel * adel);
  q.no_unkozai = el.mean_motion_rad_min / (1.0 + del);
  q.ao = std::pow(g.xke / q.no_unkozai, x2o3);
  q.sinio = std::sin(el.inclination_rad);
  const double po = q.ao * q.omeosq;
  q.con42 = 1.0 - 5.0 * q.cosio2;
  q.con41 = -q.con42 - q.cosio2 - q.cosio2;
  q.posq = po * po;
  q.rp = q.ao * (1.0 - el.eccentricity);
  return q;
}

/// The density function's s and (q0 - s)^4, earth radii ([STR3] §6): s is 78 km above the
/// surface; for perigees below 156 km, perigee - 78 km, and 20 km below 98 km (sgp4fix: the
/// fourth powers as products).
struct atmosphere {
  double sfour, qzms24;
};

atmosphere density_parameters(double rp) {
  const double re = wgs72().radiusearthkm;
  const double qzms2ttemp = (120.0 - 78.0) / re;
  atmosphere a{78.0 / re + 1.0, qzms2ttemp * qzms2ttemp * qzms2ttemp * qzms2ttemp};
  const double perige = (rp - 1.0) * re;
  if (perige < 156.0) {
    const double sfour = perige < 98.0 ? 20.0 : perige - 78.0;
    const double qzms24temp = (120.0 - sfour) / re;
    a.qzms24 = qzms24temp * qzms24temp * qzms24temp * qzms24temp;
    a.sfour = sfour / re + 1.0;
  }
  return a;
}

/// The drag coefficients C1, C3 (as omgcof, xmcof), C4, C5 and eta of [STR3] §6, with the
/// epoch values delmo, sinmao that the drag's periodic terms subtract.
void drag_coefficients(const sgp4_elements& el, const epoch_quantities& q, const atmosphere& atm,
                       double tsi, near_earth_terms& n) {
  const gravity& g = wgs72();
  n.eta = q.ao * el.eccentricity * tsi;
  const double etasq = n.eta * n.eta;
  const double eeta = el.eccentricity * n.eta;
  const double psisq = std::fabs(1.0 - etasq);
  const double coef = atm.qzms24 * std::pow(tsi, 4.0);
  const double coef1 = coef / std::pow(psisq, 3.5);
  const double cc2 = coef1 * q.no_unkozai *
                     (q.ao * (1.0 + 1.5 * etasq + eeta * (4.0 + etasq)) +
                      0.375 * g.j2 * tsi / psisq * q.con41 * (8.0 + 3.0 * etasq * (8.0 + etasq)));
  n.cc1 = el.bstar * cc2;
  double cc3 = 0.0;
  if (el.eccentricity > 1.0e-4)
    cc3 = -2.0 * coef * tsi * g.j3oj2 * q.no_unkozai * q.sinio / el.eccentricity;
  n.cc4 = 2.0 * q.no_unkozai * coef1 * q.ao * q.omeosq *
          (n.eta * (2.0 + 0.5 * etasq) + el.eccentricity * (0.5 + 2.0 * etasq) -
           g.j2 * tsi / (q.ao * psisq) *
               (-3.0 * q.con41 * (1.0 - 2.0 * eeta + etasq * (1.5 - 0.5 * eeta)) +
                0.75 * n.x1mth2 * (2.0 * etasq - eeta * (1.0 + etasq)) *
                    std::cos(2.0 * el.argument_of_perigee_rad)));
  n.cc5 = 2.0 * coef1 * q.ao * q.omeosq * (1.0 + 2.75 * (etasq + eeta) + eeta * etasq);
  n.omgcof = el.bstar * cc3 * std::cos(el.argument_of_perigee_rad);
  if (el.eccentricity > 1.0e-4) n.xmcof = -x2o3 * coef * el.bstar / eeta;
  n.t2cof = 1.5 * n.cc1;
  const double delmotemp = 1.0 + n.eta * std::cos(el.mean_anomaly_rad);
  n.delmo = delmotemp * delmotemp * delmotemp;
  n.sinmao = std::sin(el.mean_anomaly_rad);
}

/// The secular rates of M, omega, Omega from J2 and J4 (and the drag's effect on the node,
/// nodecf), and the J3 long-period coefficients xlcof, aycof ([STR3] §6).
void gravity_rates(const epoch_quantities& q, near_earth_terms& n) {
  const gravity& g = wgs72();
  const double pinvsq = 1.0 / q.posq;
  const double cosio4 = q.cosio2 * q.cosio2;
  const double temp1 = 1.5 * g.j2 * pinvsq * q.no_unkozai;
  const double temp2 = 0.5 * temp1 * g.j2 * pinvsq;
  const double temp3 = -0.46875 * g.j4 * pinvsq * pinvsq * q.no_unkozai;
  n.mdot = q.no_unkozai + 0.5 * temp1 * q.rteosq * q.con41 +
           0.0625 * temp2 * q.rteosq * (13.0 - 78.0 * q.cosio2 + 137.0 * cosio4);
  n.argpdot = -0.5 * temp1 * q.con42 + 0.0625 * temp2 * (7.0 - 114.0 * q.cosio2 + 395.0 * cosio4) +
              temp3 * (3.0 - 36.0 * q.cosio2 + 49.0 * cosio4);
  const double xhdot1 = -temp1 * q.cosio;
  n.nodedot =
      xhdot1 +
      (0.5 * temp2 * (4.0 - 19.0 * q.cosio2) + 2.0 * temp3 * (3.0 - 7.0 * q.cosio2)) * q.cosio;
  n.nodecf = 3.5 * q.omeosq * xhdot1 * n.cc1;
  // sgp4fix: no division by zero where i = 180 deg.
  const double one_plus_cos = std::fabs(q.cosio + 1.0) > 1.5e-12 ? 1.0 + q.cosio : temp4;
  n.xlcof = -0.25 * g.j3oj2 * q.sinio * (3.0 + 5.0 * q.cosio) / one_plus_cos;
  n.aycof = -0.5 * g.j3oj2 * q.sinio;
}

/// The drag's t^3, t^4, t^5 terms ([STR3] §6: D2, D3, D4), which `isimp` orbits go without.
void higher_order_drag(const epoch_quantities& q, const atmosphere& atm, double tsi,
                       near_earth_terms& n) {
  const double cc1sq = n.cc1 * n.cc1;
  n.d2 = 4.0 * q.ao * tsi * cc1sq;
  const double temp = n.d2 * tsi * n.cc1 / 3.0;
  n.d3 = (17.0 * q.ao + atm.sfour) * temp;
  n.d4 = 0.5 * temp * q.ao * tsi * (221.0 * q.ao + 31.0 * atm.sfour) * n.cc1;
  n.t3cof = n.d2 + 2.0 * cc1sq;
  n.t4cof = 0.25 * (3.0 * n.d3 + n.cc1 * (12.0 * n.d2 + 10.0 * cc1sq));
  n.t5cof = 0.2 * (3.0 * n.d4 + 12.0 * n.cc1 * n.d3 + 6.0 * n.d2 * n.d2 +
                   15.0 * cc1sq * (2.0 * n.d2 + cc1sq));
}

/// sgp4init, near-earth part. `isimp` (perigee below 220 km, or deep space) drops the
/// higher-order drag terms, as [STR3] does.
near_earth_terms near_earth_init(const sgp4_elements& el, const epoch_quantities& q,
                                 bool deep_space) {
  near_earth_terms n{};
  n.no_unkozai = q.no_unkozai;
  n.con41 = q.con41;
  n.x1mth2 = 1.0 - q.cosio2;
  n.x7thm1 = 7.0 * q.cosio2 - 1.0;
  n.isimp = deep_space || q.rp < 220.0 / wgs72().radiusearthkm + 1.0;
  const atmosphere atm = density_parameters(q.rp);
  const double tsi = 1.0 / (q.ao - atm.sfour);
  drag_coefficients(el, q, atm, tsi, n);
  gravity_rates(q, n);
  if (!n.isimp) higher_order_drag(q, atm, tsi, n);
  return n;
}

// ---- dscom: the Sun's and the Moon's terms ------------------------------------------------

/// A perturbing body's orbit seen from the satellite's (dscom's zcosg .. zsinh, cc): cosine and
/// sine of its argument g, of its inclination i, of its node relative to the satellite's, h,
/// and its strength cc (c1ss, c1l).
struct body_orientation {
  double zcosg, zsing, zcosi, zsini, zcosh, zsinh, cc;
};

/// The satellite's angles at epoch as dscom uses them.
struct satellite_angles {
  double sinim, cosim, sinomm, cosomm, em, emsq, betasq, rtemsq, xnoi;
};

/// dscom's loop body for one body: its s1..s7 and z1..z33 ([STR3] §10, the DEEP initialisation;
/// the Sun's are dscom's ss1.., sz1.., the Moon's s1.., z1..).
struct body_terms {
  double s1, s2, s3, s4, s5, s6, s7;
  double z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33;
};

body_terms body_terms_of(const body_orientation& b, const satellite_angles& s) {
  const double a1 = b.zcosg * b.zcosh + b.zsing * b.zcosi * b.zsinh;
  const double a3 = -b.zsing * b.zcosh + b.zcosg * b.zcosi * b.zsinh;
  const double a7 = -b.zcosg * b.zsinh + b.zsing * b.zcosi * b.zcosh;
  const double a8 = b.zsing * b.zsini;
  const double a9 = b.zsing * b.zsinh + b.zcosg * b.zcosi * b.zcosh;
  const double a10 = b.zcosg * b.zsini;
  const double a2 = s.cosim * a7 + s.sinim * a8;
  const double a4 = s.cosim * a9 + s.sinim * a10;
  const double a5 = -s.sinim * a7 + s.cosim * a8;
  const double a6 = -s.sinim * a9 + s.cosim * a10;
  const double x1 = a1 * s.cosomm + a2 * s.sinomm;
  const double x2 = a3 * s.cosomm + a4 * s.sinomm;
  const double x3 = -a1 * s.sinomm + a2 * s.cosomm;
  const double x4 = -a3 * s.sinomm + a4 * s.cosomm;
  const double x5 = a5 * s.sinomm;
  const double x6 = a6 * s.sinomm;
  const double x7 = a5 * s.cosomm;
  const double x8 = a6 * s.cosomm;
  const double emsq = s.emsq;
  body_terms t{};
  t.z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
  t.z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
  t.z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
  t.z1 = 3.0 * (a1 * a1 + a2 * a2) + t.z31 * emsq;
  t.z2 = 6.0 * (a1 * a3 + a2 * a4) + t.z32 * emsq;
  t.z3 = 3.0 * (a3 * a3 + a4 * a4) + t.z33 * emsq;
  t.z11 = -6.0 * a1 * a5 + emsq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
  t.z12 =
      -6.0 * (a1 * a6 + a3 * a5) + emsq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
  t.z13 = -6.0 * a3 * a6 + emsq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
  t.z21 = 6.0 * a2 * a5 + emsq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
  t.z22 =
      6.0 * (a4 * a5 + a2 * a6) + emsq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
  t.z23 = 6.0 * a4 * a6 + emsq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
  t.z1 = t.z1 + t.z1 + s.betasq * t.z31;
  t.z2 = t.z2 + t.z2 + s.betasq * t.z32;
  t.z3 = t.z3 + t.z3 + s.betasq * t.z33;
  t.s3 = b.cc * s.xnoi;
  t.s2 = -0.5 * t.s3 / s.rtemsq;
  t.s4 = t.s3 * s.rtemsq;
  t.s1 = -15.0 * s.em * t.s4;
  t.s5 = x1 * x3 + x2 * x4;
  t.s6 = x2 * x3 + x1 * x4;
  t.s7 = x2 * x4 - x1 * x3;
  return t;
}

/// dscom's closing lines for one body: the long-period periodic coefficients that dpper uses
/// (se2 .. sh3 with zes for the Sun, ee2 .. xh3 with zel for the Moon).
third_body_periodics periodic_coefficients(const body_terms& t, double emsq, double ze, double zn,
                                           double mean_anomaly_at_epoch) {
  third_body_periodics p{};
  p.e2 = 2.0 * t.s1 * t.s6;
  p.e3 = 2.0 * t.s1 * t.s7;
  p.i2 = 2.0 * t.s2 * t.z12;
  p.i3 = 2.0 * t.s2 * (t.z13 - t.z11);
  p.l2 = -2.0 * t.s3 * t.z2;
  p.l3 = -2.0 * t.s3 * (t.z3 - t.z1);
  p.l4 = -2.0 * t.s3 * (-21.0 - 9.0 * emsq) * ze;
  p.gh2 = 2.0 * t.s4 * t.z32;
  p.gh3 = 2.0 * t.s4 * (t.z33 - t.z31);
  p.gh4 = -18.0 * t.s4 * ze;
  p.h2 = -2.0 * t.s2 * t.z22;
  p.h3 = -2.0 * t.s2 * (t.z23 - t.z21);
  p.eccentricity = ze;
  p.mean_motion = zn;
  p.mean_anomaly_at_epoch = mean_anomaly_at_epoch;
  return p;
}

constexpr double zes = 0.01675, zel = 0.05490;          // the Sun's and the Moon's eccentricities
constexpr double zns = 1.19459e-5, znl = 1.5835218e-4;  // their mean motions, rad/min

/// The Sun's and the Moon's terms at epoch (dscom with tc = 0, [STR3] §10): the Moon's orbit
/// from its node's regression (xnodce), then each body's s and z terms.
struct dscom_result {
  body_terms sun, moon;
  third_body_periodics sun_periodics, moon_periodics;
};

dscom_result dscom(const sgp4_elements& el, double np) {
  const double c1ss = 2.9864797e-6, c1l = 4.7968065e-7;
  const double zsinis = 0.39785416, zcosis = 0.91744867, zcosgs = 0.1945905, zsings = -0.98088458;
  satellite_angles s{};
  s.sinim = std::sin(el.inclination_rad);
  s.cosim = std::cos(el.inclination_rad);
  s.sinomm = std::sin(el.argument_of_perigee_rad);
  s.cosomm = std::cos(el.argument_of_perigee_rad);
  s.em = el.eccentricity;
  s.emsq = s.em * s.em;
  s.betasq = 1.0 - s.emsq;
  s.rtemsq = std::sqrt(s.betasq);
  s.xnoi = 1.0 / np;
  const double snodm = std::sin(el.raan_rad), cnodm = std::cos(el.raan_rad);

  const double day = el.epoch_days_since_1950 + 18261.5;  // days from 1900 January 0.5
  const double xnodce = std::fmod(4.5236020 - 9.2422029e-4 * day, twopi);
  const double stem = std::sin(xnodce), ctem = std::cos(xnodce);
  const double zcosil = 0.91375164 - 0.03568096 * ctem;
  const double zsinil = std::sqrt(1.0 - zcosil * zcosil);
  const double zsinhl = 0.089683511 * stem / zsinil;
  const double zcoshl = std::sqrt(1.0 - zsinhl * zsinhl);
  const double gam = 5.8351514 + 0.0019443680 * day;
  double zx = 0.39785416 * stem / zsinil;
  const double zy = zcoshl * ctem + 0.91744867 * zsinhl * stem;
  zx = std::atan2(zx, zy);
  zx = gam + zx - xnodce;

  dscom_result r{};
  r.sun = body_terms_of({zcosgs, zsings, zcosis, zsinis, cnodm, snodm, c1ss}, s);
  r.moon = body_terms_of({std::cos(zx), std::sin(zx), zcosil, zsinil,
                          zcoshl * cnodm + zsinhl * snodm, snodm * zcoshl - cnodm * zsinhl, c1l},
                         s);
  const double zmol = std::fmod(4.7199672 + 0.22997150 * day - gam, twopi);
  const double zmos = std::fmod(6.2565837 + 0.017201977 * day, twopi);
  r.sun_periodics = periodic_coefficients(r.sun, s.emsq, zes, zns, zmos);
  r.moon_periodics = periodic_coefficients(r.moon, s.emsq, zel, znl, zmol);
  return r;
}

// ---- dsinit: deep-space secular rates and resonances -------------------------------------

/// One body's secular rates (dsinit's ses, sis, sls, sghs, shs for the Sun; the Moon's parts
/// of dedt, didt, dmdt and sghl, shll). sgp4fix: no node rate within 3 deg of i = 0 or 180.
struct body_rates {
  double de, di, dm, dgh, dh;
};

body_rates secular_rates_of(const body_terms& t, double zn, double emsq, double inclm) {
  body_rates r{};
  r.de = t.s1 * zn * t.s5;
  r.di = t.s2 * zn * (t.z11 + t.z13);
  r.dm = -zn * t.s3 * (t.z1 + t.z3 - 14.0 - 6.0 * emsq);
  r.dgh = t.s4 * zn * (t.z31 + t.z33 - 6.0);
  r.dh = -zn * t.s2 * (t.z21 + t.z23);
  if (inclm < 5.2359877e-2 || inclm > pi - 5.2359877e-2) r.dh = 0.0;
  return r;
}

/// dsinit's lunar-solar secular rates of e, i, M, omega, Omega (per minute).
void lunar_solar_secular_rates(const sgp4_elements& el, const dscom_result& c,
                               deep_space_terms& d) {
  const double emsq = el.eccentricity * el.eccentricity;
  const double sinim = std::sin(el.inclination_rad), cosim = std::cos(el.inclination_rad);
  const body_rates sun = secular_rates_of(c.sun, zns, emsq, el.inclination_rad);
  const body_rates moon = secular_rates_of(c.moon, znl, emsq, el.inclination_rad);
  const double shs = sinim != 0.0 ? sun.dh / sinim : sun.dh;
  const double sgs = sun.dgh - cosim * shs;
  d.dedt = sun.de + moon.de;
  d.didt = sun.di + moon.di;
  d.dmdt = sun.dm + moon.dm;
  d.domdt = sgs + moon.dgh;
  d.dnodt = shs;
  if (sinim != 0.0) {
    d.domdt = d.domdt - cosim / sinim * moon.dh;
    d.dnodt = d.dnodt + moon.dh / sinim;
  }
}

/// The 12-hour resonance's G functions: Hujsak's fits in e ([STR3] §10, DPINIT).
struct half_day_g {
  double g201, g211, g310, g322, g410, g422, g520, g521, g532, g533;
};

half_day_g half_day_g_functions(double em) {
  const double emsq = em * em, eoc = em * emsq;
  half_day_g g{};
  g.g201 = -0.306 - (em - 0.64) * 0.440;
  if (em <= 0.65) {
    g.g211 = 3.616 - 13.2470 * em + 16.2900 * emsq;
    g.g310 = -19.302 + 117.3900 * em - 228.4190 * emsq + 156.5910 * eoc;
    g.g322 = -18.9068 + 109.7927 * em - 214.6334 * emsq + 146.5816 * eoc;
    g.g410 = -41.122 + 242.6940 * em - 471.0940 * emsq + 313.9530 * eoc;
    g.g422 = -146.407 + 841.8800 * em - 1629.014 * emsq + 1083.4350 * eoc;
    g.g520 = -532.114 + 3017.977 * em - 5740.032 * emsq + 3708.2760 * eoc;
  } else {
    g.g211 = -72.099 + 331.819 * em - 508.738 * emsq + 266.724 * eoc;
    g.g310 = -346.844 + 1582.851 * em - 2415.925 * emsq + 1246.113 * eoc;
    g.g322 = -342.585 + 1554.908 * em - 2366.899 * emsq + 1215.972 * eoc;
    g.g410 = -1052.797 + 4758.686 * em - 7193.992 * emsq + 3651.957 * eoc;
    g.g422 = -3581.690 + 16178.110 * em - 24462.770 * emsq + 12422.520 * eoc;
    g.g520 = em > 0.715 ? -5149.66 + 29936.92 * em - 54087.36 * emsq + 31324.56 * eoc
                        : 1464.74 - 4664.75 * em + 3763.64 * emsq;
  }
  if (em < 0.7) {
    g.g533 = -919.22770 + 4988.6100 * em - 9064.7700 * emsq + 5542.21 * eoc;
    g.g521 = -822.71072 + 4568.6173 * em - 8491.4146 * emsq + 5337.524 * eoc;
    g.g532 = -853.66600 + 4690.2500 * em - 8624.7700 * emsq + 5341.4 * eoc;
  } else {
    g.g533 = -37995.780 + 161616.52 * em - 229838.20 * emsq + 109377.94 * eoc;
    g.g521 = -51752.104 + 218913.95 * em - 309468.16 * emsq + 146349.42 * eoc;
    g.g532 = -40023.880 + 170470.89 * em - 242699.48 * emsq + 115605.82 * eoc;
  }
  return g;
}

/// The 12-hour resonance's strengths d2201 .. d5433: the F functions of the inclination times
/// the G functions of e times (3 n^2 / a^l) and the geopotential's root_lm ([STR3] §10).
void half_day_resonance(const sgp4_elements& el, double nm, double aonv, deep_space_terms& d) {
  const double sinim = std::sin(el.inclination_rad), cosim = std::cos(el.inclination_rad);
  const double cosisq = cosim * cosim;
  const half_day_g g = half_day_g_functions(el.eccentricity);
  const double sini2 = sinim * sinim;
  const double f220 = 0.75 * (1.0 + 2.0 * cosim + cosisq);
  const double f221 = 1.5 * sini2;
  const double f321 = 1.875 * sinim * (1.0 - 2.0 * cosim - 3.0 * cosisq);
  const double f322 = -1.875 * sinim * (1.0 + 2.0 * cosim - 3.0 * cosisq);
  const double f441 = 35.0 * sini2 * f220;
  const double f442 = 39.3750 * sini2 * sini2;
  const double f522 = 9.84375 * sinim *
                      (sini2 * (1.0 - 2.0 * cosim - 5.0 * cosisq) +
                       0.33333333 * (-2.0 + 4.0 * cosim + 6.0 * cosisq));
  const double f523 = sinim * (4.92187512 * sini2 * (-2.0 - 4.0 * cosim + 10.0 * cosisq) +
                               6.56250012 * (1.0 + 2.0 * cosim - 3.0 * cosisq));
  const double f542 =
      29.53125 * sinim * (2.0 - 8.0 * cosim + cosisq * (-12.0 + 8.0 * cosim + 10.0 * cosisq));
  const double f543 =
      29.53125 * sinim * (-2.0 - 8.0 * cosim + cosisq * (12.0 + 8.0 * cosim - 10.0 * cosisq));
  const double root22 = 1.7891679e-6, root32 = 3.7393792e-7, root44 = 7.3636953e-9;
  const double root52 = 1.1428639e-7, root54 = 2.1765803e-9;
  const double xno2 = nm * nm, ainv2 = aonv * aonv;
  double temp1 = 3.0 * xno2 * ainv2;
  double temp = temp1 * root22;
  d.d2201 = temp * f220 * g.g201;
  d.d2211 = temp * f221 * g.g211;
  temp1 = temp1 * aonv;
  temp = temp1 * root32;
  d.d3210 = temp * f321 * g.g310;
  d.d3222 = temp * f322 * g.g322;
  temp1 = temp1 * aonv;
  temp = 2.0 * temp1 * root44;
  d.d4410 = temp * f441 * g.g410;
  d.d4422 = temp * f442 * g.g422;
  temp1 = temp1 * aonv;
  temp = temp1 * root52;
  d.d5220 = temp * f522 * g.g520;
  d.d5232 = temp * f523 * g.g532;
  temp = 2.0 * temp1 * root54;
  d.d5421 = temp * f542 * g.g521;
  d.d5433 = temp * f543 * g.g533;
}

/// The 24-hour (geosynchronous) resonance's strengths ([STR3] §10).
void synchronous_resonance(const sgp4_elements& el, double nm, double aonv, deep_space_terms& d) {
  const double q22 = 1.7891679e-6, q31 = 2.1460748e-6, q33 = 2.2123015e-7;
  const double emsq = el.eccentricity * el.eccentricity;
  const double sinim = std::sin(el.inclination_rad), cosim = std::cos(el.inclination_rad);
  const double g200 = 1.0 + emsq * (-2.5 + 0.8125 * emsq);
  const double g310 = 1.0 + 2.0 * emsq;
  const double g300 = 1.0 + emsq * (-6.0 + 6.60937 * emsq);
  const double f220 = 0.75 * (1.0 + cosim) * (1.0 + cosim);
  const double f311 = 0.9375 * sinim * sinim * (1.0 + 3.0 * cosim) - 0.75 * (1.0 + cosim);
  double f330 = 1.0 + cosim;
  f330 = 1.875 * f330 * f330 * f330;
  const double del1 = 3.0 * nm * nm * aonv * aonv;
  d.del2 = 2.0 * del1 * f220 * g200 * q22;
  d.del3 = 3.0 * del1 * f330 * g300 * q33 * aonv;
  d.del1 = del1 * f311 * g310 * q31 * aonv;
}

/// dsinit: which resonance (a period near 24 h, or near 12 h with e >= 0.5), and the
/// resonance angle at epoch xlamo with its rate offset xfact.
void resonance_init(const sgp4_elements& el, const near_earth_terms& n, double gsto,
                    deep_space_terms& d) {
  const double nm = n.no_unkozai, em = el.eccentricity;
  if (0.0034906585 < nm && nm < 0.0052359877) d.irez = sgp4_resonance::synchronous;
  if (8.26e-3 <= nm && nm <= 9.24e-3 && em >= 0.5) d.irez = sgp4_resonance::half_day;
  if (d.irez == sgp4_resonance::none) return;
  const double theta = std::fmod(gsto, twopi);  // gsto + tc rptim at tc = 0
  const double aonv = std::pow(nm / wgs72().xke, x2o3);
  if (d.irez == sgp4_resonance::half_day) {
    half_day_resonance(el, nm, aonv, d);
    d.xlamo = std::fmod(el.mean_anomaly_rad + el.raan_rad + el.raan_rad - theta - theta, twopi);
    d.xfact = n.mdot + d.dmdt + 2.0 * (n.nodedot + d.dnodt - rptim) - n.no_unkozai;
  } else {
    synchronous_resonance(el, nm, aonv, d);
    const double xpidot = n.argpdot + n.nodedot;
    d.xlamo =
        std::fmod(el.mean_anomaly_rad + el.raan_rad + el.argument_of_perigee_rad - theta, twopi);
    d.xfact = n.mdot + xpidot - rptim + d.dmdt + d.domdt + d.dnodt - n.no_unkozai;
  }
}

// ---- dspace: the resonance integration -----------------------------------------------------

/// The resonance angle's and mean motion's derivatives at (xli, xni) after atime minutes
/// (dspace's "dot terms").
struct resonance_rates {
  double xndt, xnddt, xldot;
};

resonance_rates resonance_derivatives(const deep_space_terms& d, double xli, double xni,
                                      double atime, double argpo, double argpdot) {
  const double fasx2 = 0.13130908, fasx4 = 2.8843198, fasx6 = 0.37448087;
  const double g22 = 5.7686396, g32 = 0.95240898, g44 = 1.8014998, g52 = 1.0508330;
  const double g54 = 4.4108898;
  resonance_rates r{};
  r.xldot = xni + d.xfact;
  if (d.irez != sgp4_resonance::half_day) {
    r.xndt = d.del1 * std::sin(xli - fasx2) + d.del2 * std::sin(2.0 * (xli - fasx4)) +
             d.del3 * std::sin(3.0 * (xli - fasx6));
    r.xnddt = d.del1 * std::cos(xli - fasx2) + 2.0 * d.del2 * std::cos(2.0 * (xli - fasx4)) +
              3.0 * d.del3 * std::cos(3.0 * (xli - fasx6));
  } else {
    const double xomi = argpo + argpdot * atime;
    const double x2omi = xomi + xomi, x2li = xli + xli;
    r.xndt = d.d2201 * std::sin(x2omi + xli - g22) + d.d2211 * std::sin(xli - g22) +
             d.d3210 * std::sin(xomi + xli - g32) + d.d3222 * std::sin(-xomi + xli - g32) +
             d.d4410 * std::sin(x2omi + x2li - g44) + d.d4422 * std::sin(x2li - g44) +
             d.d5220 * std::sin(xomi + xli - g52) + d.d5232 * std::sin(-xomi + xli - g52) +
             d.d5421 * std::sin(xomi + x2li - g54) + d.d5433 * std::sin(-xomi + x2li - g54);
    r.xnddt =
        d.d2201 * std::cos(x2omi + xli - g22) + d.d2211 * std::cos(xli - g22) +
        d.d3210 * std::cos(xomi + xli - g32) + d.d3222 * std::cos(-xomi + xli - g32) +
        d.d5220 * std::cos(xomi + xli - g52) + d.d5232 * std::cos(-xomi + xli - g52) +
        2.0 * (d.d4410 * std::cos(x2omi + x2li - g44) + d.d4422 * std::cos(x2li - g44) +
               d.d5421 * std::cos(xomi + x2li - g54) + d.d5433 * std::cos(-xomi + x2li - g54));
  }
  r.xnddt = r.xnddt * r.xldot;
  return r;
}

/// The mean motion and resonance angle at t (min): second-order Taylor steps of 720 min toward
/// t, then a partial step of ft = t - atime (dspace's integrator; sgp4fix: the end test after
/// the derivatives). The steps start from `node` where t lies beyond it on its side of epoch
/// (as the reference resumes between calls), else from epoch; `node` is left at the last one.
/// The nodes are the same either way, so are the results.
struct resonance_solution {
  double nm, xl;
};

resonance_solution integrate_resonance(const deep_space_terms& d, double t, double no, double argpo,
                                       double argpdot, resonance_node& node) {
  const double stepp = 720.0, step2 = 259200.0;  // step and step^2 / 2
  if (node.atime == 0.0 || t * node.atime <= 0.0 || std::fabs(t) < std::fabs(node.atime))
    node = {0.0, d.xlamo, no};
  const double delt = t > 0.0 ? stepp : -stepp;
  for (;;) {
    const resonance_rates r =
        resonance_derivatives(d, node.xli, node.xni, node.atime, argpo, argpdot);
    if (!(std::fabs(t - node.atime) >= stepp)) {
      const double ft = t - node.atime;
      return {node.xni + r.xndt * ft + r.xnddt * ft * ft * 0.5,
              node.xli + r.xldot * ft + r.xndt * ft * ft * 0.5};
    }
    node.xli = node.xli + r.xldot * delt + r.xndt * step2;
    node.xni = node.xni + r.xndt * delt + r.xnddt * step2;
    node.atime = node.atime + delt;
  }
}

// ---- sgp4: the state at a time -------------------------------------------------------------

/// The sine and cosine terms that depend on the (possibly perturbed) inclination: the
/// reference keeps them from epoch in SGP4 and recomputes them at each time in SDP4.
struct inclination_terms {
  double aycof, xlcof, con41, x1mth2, x7thm1;
};

inclination_terms deep_space_inclination_terms(double sinip, double cosip) {
  const gravity& g = wgs72();
  const double one_plus_cos = std::fabs(cosip + 1.0) > 1.5e-12 ? 1.0 + cosip : temp4;
  const double cosisq = cosip * cosip;
  return {-0.5 * g.j3oj2 * sinip, -0.25 * g.j3oj2 * sinip * (3.0 + 5.0 * cosip) / one_plus_cos,
          3.0 * cosisq - 1.0, 1.0 - cosisq, 7.0 * cosisq - 1.0};
}

/// Kepler's equation in SGP4's variables, U = E + omega with axN = e cos omega, ayN = e sin
/// omega ([STR3] §6): Newton from E + omega = U, steps clamped to 0.95 rad, at most 10 steps,
/// until a step is below 1e-12 (sgp4fix). Kept as the reference has it, rather than the
/// project's solve_kepler, so that the results are the reference's: the sine and cosine are
/// those of the iterate before the last step, as there.
struct kepler_result {
  double sineo1, coseo1;
};

kepler_result solve_sgp4_kepler(double u, double axnl, double aynl) {
  double eo1 = u, tem5 = 9999.9, sineo1 = 0.0, coseo1 = 1.0;
  for (int ktr = 1; std::fabs(tem5) >= 1.0e-12 && ktr <= 10; ++ktr) {
    sineo1 = std::sin(eo1);
    coseo1 = std::cos(eo1);
    tem5 = 1.0 - coseo1 * axnl - sineo1 * aynl;
    tem5 = (u - aynl * coseo1 + axnl * sineo1 - eo1) / tem5;
    if (std::fabs(tem5) >= 0.95) tem5 = tem5 > 0.0 ? 0.95 : -0.95;
    eo1 = eo1 + tem5;
  }
  return {sineo1, coseo1};
}

}  // namespace

/// The mean elements at t, from one stage of state_at to the next.
struct sgp4_propagator::mean_state {
  double em, inclm, nodem, argpm, mm, nm;  // averaged elements (sgp4's em .. nm)
  double tempa, tempe, templ;              // drag factors on a, e and the mean longitude
  double am = 0;                           // semi-major axis, earth radii
  // after the lunar-solar periodics (sgp4's ep .. mp)
  double ep = 0, xincp = 0, nodep = 0, argpp = 0, mp = 0;
};

const char* describe(sgp4_status status) noexcept {
  static constexpr enum_names<sgp4_status, 7> descriptions{{
      {sgp4_status::ok, "ok"},
      {sgp4_status::mean_eccentricity, "mean eccentricity outside [-0.001, 1)"},
      {sgp4_status::mean_motion, "mean motion not positive"},
      {sgp4_status::perturbed_eccentricity, "perturbed eccentricity outside [0, 1]"},
      {sgp4_status::semi_latus_rectum, "semi-latus rectum negative"},
      {sgp4_status::decayed, "the satellite has decayed (radius below the Earth's)"},
      {sgp4_status::invalid_input, "an element or the time is not finite"},
  }};
  return name_of(descriptions, status, "unknown status");
}

sgp4_elements mean_elements(const tle& set) noexcept {
  const double xpdotp = 1440.0 / (2.0 * pi);  // rev/day per rad/min
  sgp4_elements el{};
  // As the reference's twoline2rv: the epoch as one double Julian date, then from 1950. That
  // rounds it to the grid of doubles near JD 2.45e6 (4.7e-10 day, 40 us), and SDP4's states
  // depend on it through the Sun's and the Moon's positions at epoch: the exact epoch,
  // (jd_day_start - jd_1950) + fraction, moves tcppver.out's satellite 20413 by 4.1e-6 km
  // after 3.5 years, 20 times the verification's tolerance. The reference defines the model.
  el.epoch_days_since_1950 = (jd_day_start(set.epoch) + set.epoch.fraction_of_day) - jd_1950;
  el.bstar = set.bstar_per_earth_radius;
  el.eccentricity = set.eccentricity;
  el.argument_of_perigee_rad = set.argument_of_perigee_deg * deg2rad;
  el.inclination_rad = set.inclination_deg * deg2rad;
  el.mean_anomaly_rad = set.mean_anomaly_deg * deg2rad;
  el.mean_motion_rad_min = set.mean_motion_rev_day / xpdotp;
  el.raan_rad = set.raan_deg * deg2rad;
  return el;
}

sgp4_propagator::sgp4_propagator(const sgp4_elements& elements, sgp4_mode mode) noexcept
    : epoch_(elements), mode_(mode) {
  initialize(elements);
}

sgp4_propagator::sgp4_propagator(const tle& set, sgp4_mode mode) noexcept
    : sgp4_propagator(mean_elements(set), mode) {}

void sgp4_propagator::initialize(const sgp4_elements& el) noexcept {
  const double values[] = {el.epoch_days_since_1950,   el.bstar,           el.eccentricity,
                           el.argument_of_perigee_rad, el.inclination_rad, el.mean_anomaly_rad,
                           el.mean_motion_rad_min,     el.raan_rad};
  for (double v : values)
    if (!std::isfinite(v)) input_status_ = sgp4_status::invalid_input;
  if (input_status_ == sgp4_status::ok && !(el.eccentricity >= 0.0 && el.eccentricity < 1.0))
    input_status_ = sgp4_status::mean_eccentricity;
  if (input_status_ == sgp4_status::ok && !(el.mean_motion_rad_min > 0.0))
    input_status_ = sgp4_status::mean_motion;
  if (input_status_ != sgp4_status::ok) {  // state_at gives this status at every time
    status_at_epoch_ = input_status_;
    return;
  }

  const epoch_quantities q = initl(el);
  gsto_ = mode_ == sgp4_mode::afspc ? gstime_afspc(el.epoch_days_since_1950)
                                    : gstime(el.epoch_days_since_1950 + jd_1950);
  deep_space_ = twopi / q.no_unkozai >= 225.0;  // period of 225 min or more
  near_ = near_earth_init(el, q, deep_space_);
  if (deep_space_) {
    // sgp4init's call of dpper at epoch (init = 'y') changes nothing, and the epoch values of
    // the periodics it would subtract (peo .. pho) stay zero in the reference: left out.
    const dscom_result c = dscom(el, q.no_unkozai);
    deep_.sun = c.sun_periodics;
    deep_.moon = c.moon_periodics;
    lunar_solar_secular_rates(el, c, deep_);
    resonance_init(el, near_, gsto_, deep_);
  }
  status_at_epoch_ = state_at(0.0).status;
}

/// sgp4's first block: secular gravity and atmospheric drag ([STR3] §6).
sgp4_propagator::mean_state sgp4_propagator::secular(double t) const noexcept {
  const near_earth_terms& n = near_;
  const double xmdf = epoch_.mean_anomaly_rad + n.mdot * t;
  const double argpdf = epoch_.argument_of_perigee_rad + n.argpdot * t;
  const double nodedf = epoch_.raan_rad + n.nodedot * t;
  const double t2 = t * t;
  mean_state m{};
  m.em = epoch_.eccentricity;
  m.inclm = epoch_.inclination_rad;
  m.nodem = nodedf + n.nodecf * t2;
  m.argpm = argpdf;
  m.mm = xmdf;
  m.nm = n.no_unkozai;
  m.tempa = 1.0 - n.cc1 * t;
  m.tempe = epoch_.bstar * n.cc4 * t;
  m.templ = n.t2cof * t2;
  if (!n.isimp) {
    const double delomg = n.omgcof * t;
    const double delmtemp = 1.0 + n.eta * std::cos(xmdf);
    const double delm = n.xmcof * (delmtemp * delmtemp * delmtemp - n.delmo);
    const double temp = delomg + delm;
    m.mm = xmdf + temp;
    m.argpm = argpdf - temp;
    const double t3 = t2 * t, t4 = t3 * t;
    m.tempa = m.tempa - n.d2 * t2 - n.d3 * t3 - n.d4 * t4;
    m.tempe = m.tempe + epoch_.bstar * n.cc5 * (std::sin(m.mm) - n.sinmao);
    m.templ = m.templ + n.t3cof * t3 + t4 * (n.t4cof + t * n.t5cof);
  }
  return m;
}

/// dspace: lunar-solar secular drift, and the resonance's mean motion and mean anomaly.
void sgp4_propagator::deep_space_secular(double t, mean_state& m,
                                         resonance_cursor& cursor) const noexcept {
  const deep_space_terms& d = deep_;
  const double theta = std::fmod(gsto_ + t * rptim, twopi);
  m.em = m.em + d.dedt * t;
  m.inclm = m.inclm + d.didt * t;
  m.argpm = m.argpm + d.domdt * t;
  m.nodem = m.nodem + d.dnodt * t;
  m.mm = m.mm + d.dmdt * t;
  if (d.irez == sgp4_resonance::none) return;
  const double no = near_.no_unkozai;
  const resonance_solution s =
      integrate_resonance(d, t, no, epoch_.argument_of_perigee_rad, near_.argpdot, cursor.node_);
  m.mm = d.irez != sgp4_resonance::synchronous ? s.xl - 2.0 * m.nodem + 2.0 * theta
                                               : s.xl - m.nodem - m.argpm + theta;
  const double dndt = s.nm - no;
  m.nm = no + dndt;
}

/// dpper at t (init = 'n'): the Sun's and the Moon's long-period periodics added to e, i,
/// Omega, omega, M; below i = 0.2 rad with Lyddane's modification (sgp4fix: the test on the
/// perturbed inclination, as GSFC's code; the node kept continuous across 2 pi).
void sgp4_propagator::lunar_solar_periodics(double t, mean_state& m) const noexcept {
  struct sums {
    double pe = 0, pinc = 0, pl = 0, pgh = 0, ph = 0;
  } s;
  for (const third_body_periodics* b : {&deep_.sun, &deep_.moon}) {
    const double zm = b->mean_anomaly_at_epoch + b->mean_motion * t;
    const double zf = zm + 2.0 * b->eccentricity * std::sin(zm);
    const double sinzf = std::sin(zf);
    const double f2 = 0.5 * sinzf * sinzf - 0.25;
    const double f3 = -0.5 * sinzf * std::cos(zf);
    s.pe += b->e2 * f2 + b->e3 * f3;  // the Sun's term first, then + the Moon's, as dpper
    s.pinc += b->i2 * f2 + b->i3 * f3;
    s.pl += b->l2 * f2 + b->l3 * f3 + b->l4 * sinzf;
    s.pgh += b->gh2 * f2 + b->gh3 * f3 + b->gh4 * sinzf;
    s.ph += b->h2 * f2 + b->h3 * f3;
  }
  m.xincp = m.xincp + s.pinc;
  m.ep = m.ep + s.pe;
  const double sinip = std::sin(m.xincp), cosip = std::cos(m.xincp);
  if (m.xincp >= 0.2) {
    s.ph = s.ph / sinip;
    s.pgh = s.pgh - cosip * s.ph;
    m.argpp = m.argpp + s.pgh;
    m.nodep = m.nodep + s.ph;
    m.mp = m.mp + s.pl;
    return;
  }
  const bool afspc = mode_ == sgp4_mode::afspc;
  const double sinop = std::sin(m.nodep), cosop = std::cos(m.nodep);
  const double alfdp = sinip * sinop + (s.ph * cosop + s.pinc * cosip * sinop);
  const double betdp = sinip * cosop + (-s.ph * sinop + s.pinc * cosip * cosop);
  m.nodep = std::fmod(m.nodep, twopi);
  if (m.nodep < 0.0 && afspc) m.nodep = m.nodep + twopi;  // sgp4fix: AFSPC's intrinsics
  double xls = m.mp + m.argpp + cosip * m.nodep;
  const double dls = s.pl + s.pgh - s.pinc * m.nodep * sinip;
  xls = xls + dls;
  const double xnoh = m.nodep;
  m.nodep = std::atan2(alfdp, betdp);
  if (m.nodep < 0.0 && afspc) m.nodep = m.nodep + twopi;
  if (std::fabs(xnoh - m.nodep) > pi) m.nodep += m.nodep < xnoh ? twopi : -twopi;
  m.mp = m.mp + s.pl;
  m.argpp = xls - m.mp - cosip * m.nodep;
}

/// The long-period periodics, Kepler's equation, the short-period periodics and the TEME
/// position and velocity ([STR3] §6, the last blocks of [V06]'s sgp4).
teme_state sgp4_propagator::position_velocity(const mean_state& m) const noexcept {
  const gravity& g = wgs72();
  const double sinip = std::sin(m.xincp), cosip = std::cos(m.xincp);
  const inclination_terms k = deep_space_ ? deep_space_inclination_terms(sinip, cosip)
                                          : inclination_terms{near_.aycof, near_.xlcof, near_.con41,
                                                              near_.x1mth2, near_.x7thm1};
  const double axnl = m.ep * std::cos(m.argpp);
  double temp = 1.0 / (m.am * (1.0 - m.ep * m.ep));
  const double aynl = m.ep * std::sin(m.argpp) + temp * k.aycof;
  const double xl = m.mp + m.argpp + m.nodep + temp * k.xlcof * axnl;

  const double u = std::fmod(xl - m.nodep, twopi);
  const kepler_result e = solve_sgp4_kepler(u, axnl, aynl);
  const double ecose = axnl * e.coseo1 + aynl * e.sineo1;
  const double esine = axnl * e.sineo1 - aynl * e.coseo1;
  const double el2 = axnl * axnl + aynl * aynl;
  const double pl = m.am * (1.0 - el2);
  if (pl < 0.0) return failed(sgp4_status::semi_latus_rectum);

  const double rl = m.am * (1.0 - ecose);
  const double rdotl = std::sqrt(m.am) * esine / rl;
  const double rvdotl = std::sqrt(pl) / rl;
  const double betal = std::sqrt(1.0 - el2);
  temp = esine / (1.0 + betal);
  const double sinu = m.am / rl * (e.sineo1 - aynl - axnl * temp);
  const double cosu = m.am / rl * (e.coseo1 - axnl + aynl * temp);
  double su = std::atan2(sinu, cosu);
  const double sin2u = (cosu + cosu) * sinu;
  const double cos2u = 1.0 - 2.0 * sinu * sinu;
  temp = 1.0 / pl;
  const double temp1 = 0.5 * g.j2 * temp;
  const double temp2 = temp1 * temp;

  const double mrt = rl * (1.0 - 1.5 * temp2 * betal * k.con41) + 0.5 * temp1 * k.x1mth2 * cos2u;
  su = su - 0.25 * temp2 * k.x7thm1 * sin2u;
  const double xnode = m.nodep + 1.5 * temp2 * cosip * sin2u;
  const double xinc = m.xincp + 1.5 * temp2 * cosip * sinip * cos2u;
  const double mvt = rdotl - m.nm * temp1 * k.x1mth2 * sin2u / g.xke;
  const double rvdot = rvdotl + m.nm * temp1 * (k.x1mth2 * cos2u + 1.5 * k.con41) / g.xke;

  // Orientation: u toward the satellite, v along its motion, in TEME.
  const double sinsu = std::sin(su), cossu = std::cos(su);
  const double snod = std::sin(xnode), cnod = std::cos(xnode);
  const double sini = std::sin(xinc), cosi = std::cos(xinc);
  const double xmx = -snod * cosi, xmy = cnod * cosi;
  const vec3<double> uv(xmx * sinsu + cnod * cossu, xmy * sinsu + snod * cossu, sini * sinsu);
  const vec3<double> vv(xmx * cossu - cnod * sinsu, xmy * cossu - snod * sinsu, sini * cossu);
  const double vkmpersec = g.radiusearthkm * g.xke / 60.0;
  teme_state out;
  out.r_teme_km = vec3<double>((mrt * uv.x) * g.radiusearthkm, (mrt * uv.y) * g.radiusearthkm,
                               (mrt * uv.z) * g.radiusearthkm);
  out.v_teme_km_s =
      vec3<double>((mvt * uv.x + rvdot * vv.x) * vkmpersec, (mvt * uv.y + rvdot * vv.y) * vkmpersec,
                   (mvt * uv.z + rvdot * vv.z) * vkmpersec);
  // sgp4fix: a decayed satellite still gets its (underground) state, flagged.
  out.status = mrt < 1.0 ? sgp4_status::decayed : sgp4_status::ok;
  return out;
}

teme_state sgp4_propagator::state_at(double t) const noexcept {
  resonance_cursor from_epoch{};
  return state_at(t, from_epoch);
}

void sgp4_propagator::states_at(const double* t, teme_state* out,
                                std::size_t count) const noexcept {
  resonance_cursor cursor{};
  for (std::size_t i = 0; i < count; ++i) out[i] = state_at(t[i], cursor);
}

teme_state sgp4_propagator::state_at(double t, resonance_cursor& cursor) const noexcept {
  if (input_status_ != sgp4_status::ok) return failed(input_status_);
  if (!std::isfinite(t)) return failed(sgp4_status::invalid_input);
  const gravity& g = wgs72();
  mean_state m = secular(t);
  if (deep_space_) deep_space_secular(t, m, cursor);
  if (m.nm <= 0.0) return failed(sgp4_status::mean_motion);
  m.am = std::pow(g.xke / m.nm, x2o3) * m.tempa * m.tempa;
  m.nm = g.xke / std::pow(m.am, 1.5);
  m.em = m.em - m.tempe;
  // sgp4fix: the reference's test a < 0.95 earth radii is commented out there, and here.
  if (m.em >= 1.0 || m.em < -0.001) return failed(sgp4_status::mean_eccentricity);
  if (m.em < 1.0e-6) m.em = 1.0e-6;  // sgp4fix: no division by zero
  m.mm = m.mm + near_.no_unkozai * m.templ;
  double xlm = m.mm + m.argpm + m.nodem;
  m.nodem = std::fmod(m.nodem, twopi);
  m.argpm = std::fmod(m.argpm, twopi);
  xlm = std::fmod(xlm, twopi);
  m.mm = std::fmod(xlm - m.argpm - m.nodem, twopi);

  m.ep = m.em;
  m.xincp = m.inclm;
  m.argpp = m.argpm;
  m.nodep = m.nodem;
  m.mp = m.mm;
  if (deep_space_) {
    lunar_solar_periodics(t, m);
    if (m.xincp < 0.0) {  // a negative inclination: the same orbit with i, Omega, omega turned
      m.xincp = -m.xincp;
      m.nodep = m.nodep + pi;
      m.argpp = m.argpp - pi;
    }
    if (m.ep < 0.0 || m.ep > 1.0) return failed(sgp4_status::perturbed_eccentricity);
  }
  return position_velocity(m);
}

}  // namespace conescan::orbit
