// detmath_exp.c — deterministic exp, log, pow and cbrt (hs_math.h), built as detmath.c's
// functions are: from + − × ÷, sqrt, floor and bit operations only (detmath.h), so every IEEE-754
// binary64 machine gives the same bits; tables and coefficients derived with mpmath.
#include "detmath.h"

// ---- tables (generated with mpmath) ----

// exp: ln2/EXP_N in two parts, the first of 35 bits so that k LN2_N_HI is exact for |k| < 2^18;
// exp_tab holds 2^(j/EXP_N) as hi, lo
#define EXP_N 128
#define LN2_N_HI 0x1.62e42fefc0000p-8
#define LN2_N_LO -0x1.c610ca86c3899p-44
#define INV_LN2_N 0x1.71547652b82fep+7
static const double exp_tab[2 * EXP_N] = {
	0x1.0000000000000p+0, 0x0.0p+0,
	0x1.0163da9fb3335p+0, 0x1.b61299ab8cdb7p-54,
	0x1.02c9a3e778061p+0, -0x1.19083535b085dp-56,
	0x1.04315e86e7f85p+0, -0x1.0a31c1977c96ep-54,
	0x1.059b0d3158574p+0, 0x1.d73e2a475b465p-55,
	0x1.0706b29ddf6dep+0, -0x1.c91dfe2b13c27p-55,
	0x1.0874518759bc8p+0, 0x1.186be4bb284ffp-57,
	0x1.09e3ecac6f383p+0, 0x1.1487818316136p-54,
	0x1.0b5586cf9890fp+0, 0x1.8a62e4adc610bp-54,
	0x1.0cc922b7247f7p+0, 0x1.01edc16e24f71p-54,
	0x1.0e3ec32d3d1a2p+0, 0x1.03a1727c57b53p-59,
	0x1.0fb66affed31bp+0, -0x1.b9bedc44ebd7bp-57,
	0x1.11301d0125b51p+0, -0x1.6c51039449b3ap-54,
	0x1.12abdc06c31ccp+0, -0x1.1b514b36ca5c7p-58,
	0x1.1429aaea92de0p+0, -0x1.32fbf9af1369ep-54,
	0x1.15a98c8a58e51p+0, 0x1.2406ab9eeab0ap-55,
	0x1.172b83c7d517bp+0, -0x1.19041b9d78a76p-55,
	0x1.18af9388c8deap+0, -0x1.11023d1970f6cp-54,
	0x1.1a35beb6fcb75p+0, 0x1.e5b4c7b4968e4p-55,
	0x1.1bbe084045cd4p+0, -0x1.95386352ef607p-54,
	0x1.1d4873168b9aap+0, 0x1.e016e00a2643cp-54,
	0x1.1ed5022fcd91dp+0, -0x1.1df98027bb78cp-54,
	0x1.2063b88628cd6p+0, 0x1.dc775814a8495p-55,
	0x1.21f49917ddc96p+0, 0x1.2a97e9494a5eep-55,
	0x1.2387a6e756238p+0, 0x1.9b07eb6c70573p-54,
	0x1.251ce4fb2a63fp+0, 0x1.ac155bef4f4a4p-55,
	0x1.26b4565e27cddp+0, 0x1.2bd339940e9d9p-55,
	0x1.284dfe1f56381p+0, -0x1.a4c3a8c3f0d7ep-54,
	0x1.29e9df51fdee1p+0, 0x1.612e8afad1255p-55,
	0x1.2b87fd0dad990p+0, -0x1.10adcd6381aa4p-59,
	0x1.2d285a6e4030bp+0, 0x1.0024754db41d5p-54,
	0x1.2ecafa93e2f56p+0, 0x1.1ca0f45d52383p-56,
	0x1.306fe0a31b715p+0, 0x1.6f46ad23182e4p-55,
	0x1.32170fc4cd831p+0, 0x1.a9ce78e18047cp-55,
	0x1.33c08b26416ffp+0, 0x1.32721843659a6p-54,
	0x1.356c55f929ff1p+0, -0x1.b5cee5c4e4628p-55,
	0x1.371a7373aa9cbp+0, -0x1.63aeabf42eae2p-54,
	0x1.38cae6d05d866p+0, -0x1.e958d3c9904bdp-54,
	0x1.3a7db34e59ff7p+0, -0x1.5e436d661f5e3p-56,
	0x1.3c32dc313a8e5p+0, -0x1.efff8375d29c3p-54,
	0x1.3dea64c123422p+0, 0x1.ada0911f09ebcp-55,
	0x1.3fa4504ac801cp+0, -0x1.7d023f956f9f3p-54,
	0x1.4160a21f72e2ap+0, -0x1.ef3691c309278p-58,
	0x1.431f5d950a897p+0, -0x1.1c7dde35f7999p-55,
	0x1.44e086061892dp+0, 0x1.89b7a04ef80d0p-59,
	0x1.46a41ed1d0057p+0, 0x1.c944bd1648a76p-54,
	0x1.486a2b5c13cd0p+0, 0x1.3c1a3b69062f0p-56,
	0x1.4a32af0d7d3dep+0, 0x1.9cb62f3d1be56p-54,
	0x1.4bfdad5362a27p+0, 0x1.d4397afec42e2p-56,
	0x1.4dcb299fddd0dp+0, 0x1.8ecdbbc6a7833p-54,
	0x1.4f9b2769d2ca7p+0, -0x1.4b309d25957e3p-54,
	0x1.516daa2cf6642p+0, -0x1.f768569bd93efp-55,
	0x1.5342b569d4f82p+0, -0x1.07abe1db13cadp-55,
	0x1.551a4ca5d920fp+0, -0x1.d689cefede59bp-55,
	0x1.56f4736b527dap+0, 0x1.9bb2c011d93adp-54,
	0x1.58d12d497c7fdp+0, 0x1.295e15b9a1de8p-55,
	0x1.5ab07dd485429p+0, 0x1.6324c054647adp-54,
	0x1.5c9268a5946b7p+0, 0x1.c4b1b816986a2p-60,
	0x1.5e76f15ad2148p+0, 0x1.ba6f93080e65ep-54,
	0x1.605e1b976dc09p+0, -0x1.3e2429b56de47p-54,
	0x1.6247eb03a5585p+0, -0x1.383c17e40b497p-54,
	0x1.6434634ccc320p+0, -0x1.c483c759d8933p-55,
	0x1.6623882552225p+0, -0x1.bb60987591c34p-54,
	0x1.68155d44ca973p+0, 0x1.038ae44f73e65p-57,
	0x1.6a09e667f3bcdp+0, -0x1.bdd3413b26456p-54,
	0x1.6c012750bdabfp+0, -0x1.2895667ff0b0dp-56,
	0x1.6dfb23c651a2fp+0, -0x1.bbe3a683c88abp-57,
	0x1.6ff7df9519484p+0, -0x1.83c0f25860ef6p-55,
	0x1.71f75e8ec5f74p+0, -0x1.16e4786887a99p-55,
	0x1.73f9a48a58174p+0, -0x1.0a8d96c65d53cp-54,
	0x1.75feb564267c9p+0, -0x1.0245957316dd3p-54,
	0x1.780694fde5d3fp+0, 0x1.866b80a02162dp-54,
	0x1.7a11473eb0187p+0, -0x1.41577ee04992fp-55,
	0x1.7c1ed0130c132p+0, 0x1.f124cd1164dd6p-54,
	0x1.7e2f336cf4e62p+0, 0x1.05d02ba15797ep-56,
	0x1.80427543e1a12p+0, -0x1.27c86626d972bp-54,
	0x1.82589994cce13p+0, -0x1.d4c1dd41532d8p-54,
	0x1.8471a4623c7adp+0, -0x1.8d684a341cdfbp-55,
	0x1.868d99b4492edp+0, -0x1.fc6f89bd4f6bap-54,
	0x1.88ac7d98a6699p+0, 0x1.994c2f37cb53ap-54,
	0x1.8ace5422aa0dbp+0, 0x1.6e9f156864b27p-54,
	0x1.8cf3216b5448cp+0, -0x1.0d55e32e9e3aap-56,
	0x1.8f1ae99157736p+0, 0x1.5cc13a2e3976cp-55,
	0x1.9145b0b91ffc6p+0, -0x1.dd6792e582524p-54,
	0x1.93737b0cdc5e5p+0, -0x1.75fc781b57ebcp-57,
	0x1.95a44cbc8520fp+0, -0x1.64b7c96a5f039p-56,
	0x1.97d829fde4e50p+0, -0x1.d185b7c1b85d1p-54,
	0x1.9a0f170ca07bap+0, -0x1.173bd91cee632p-54,
	0x1.9c49182a3f090p+0, 0x1.c7c46b071f2bep-56,
	0x1.9e86319e32323p+0, 0x1.824ca78e64c6ep-56,
	0x1.a0c667b5de565p+0, -0x1.359495d1cd533p-54,
	0x1.a309bec4a2d33p+0, 0x1.6305c7ddc36abp-54,
	0x1.a5503b23e255dp+0, -0x1.d2f6edb8d41e1p-54,
	0x1.a799e1330b358p+0, 0x1.bcb7ecac563c7p-54,
	0x1.a9e6b5579fdbfp+0, 0x1.0fac90ef7fd31p-54,
	0x1.ac36bbfd3f37ap+0, -0x1.f9234cae76cd0p-55,
	0x1.ae89f995ad3adp+0, 0x1.7a1cd345dcc81p-54,
	0x1.b0e07298db666p+0, -0x1.bdef54c80e425p-54,
	0x1.b33a2b84f15fbp+0, -0x1.2805e3084d708p-57,
	0x1.b59728de5593ap+0, -0x1.c71dfbbba6de3p-54,
	0x1.b7f76f2fb5e47p+0, -0x1.5584f7e54ac3bp-56,
	0x1.ba5b030a1064ap+0, -0x1.efcd30e54292ep-54,
	0x1.bcc1e904bc1d2p+0, 0x1.23dd07a2d9e84p-55,
	0x1.bf2c25bd71e09p+0, -0x1.efdca3f6b9c73p-54,
	0x1.c199bdd85529cp+0, 0x1.11065895048ddp-55,
	0x1.c40ab5fffd07ap+0, 0x1.b4537e083c60ap-54,
	0x1.c67f12e57d14bp+0, 0x1.2884dff483cadp-54,
	0x1.c8f6d9406e7b5p+0, 0x1.1acbc48805c44p-56,
	0x1.cb720dcef9069p+0, 0x1.503cbd1e949dbp-56,
	0x1.cdf0b555dc3fap+0, -0x1.dd83b53829d72p-55,
	0x1.d072d4a07897cp+0, -0x1.cbc3743797a9cp-54,
	0x1.d2f87080d89f2p+0, -0x1.d487b719d8578p-54,
	0x1.d5818dcfba487p+0, 0x1.2ed02d75b3707p-55,
	0x1.d80e316c98398p+0, -0x1.11ec18beddfe8p-54,
	0x1.da9e603db3285p+0, 0x1.c2300696db532p-54,
	0x1.dd321f301b460p+0, 0x1.2da5778f018c3p-54,
	0x1.dfc97337b9b5fp+0, -0x1.1a5cd4f184b5cp-54,
	0x1.e264614f5a129p+0, -0x1.7b627817a1496p-54,
	0x1.e502ee78b3ff6p+0, 0x1.39e8980a9cc8fp-55,
	0x1.e7a51fbc74c83p+0, 0x1.2d522ca0c8de2p-54,
	0x1.ea4afa2a490dap+0, -0x1.e9c23179c2893p-54,
	0x1.ecf482d8e67f1p+0, -0x1.c93f3b411ad8cp-54,
	0x1.efa1bee615a27p+0, 0x1.dc7f486a4b6b0p-54,
	0x1.f252b376bba97p+0, 0x1.3a1a5bf0d8e43p-54,
	0x1.f50765b6e4540p+0, 0x1.9d3e12dd8a18bp-54,
	0x1.f7bfdad9cbe14p+0, -0x1.dbb12d006350ap-54,
	0x1.fa7c1819e90d8p+0, 0x1.74853f3a5931ep-55,
	0x1.fd3c22b8f71f1p+0, 0x1.2eb74966579e7p-57,
};
// ln2 in two parts, the first of 42 bits so that e LN2_HI is exact for any exponent e
#define LN2_HI 0x1.62e42fefa3800p-1
#define LN2_LO 0x1.ef35793c76730p-45
// log: for z in [1 + i/128, 1 + (i+1)/128) (halved for i >= 53), invc ~ 1/z with 9 bits so that
// z invc is exact, and -log(invc) as hi, lo
static const double log_tab[3 * 128] = {
	0x1.0000000000000p+0, 0x0.0p+0, 0x0.0p+0,
	0x1.fa00000000000p-1, 0x1.82448a388a2aap-7, 0x1.04b16137f09a0p-62,
	0x1.f600000000000p-1, 0x1.432a925980cc1p-6, -0x1.8cdaf39004192p-60,
	0x1.f200000000000p-1, 0x1.c63d2ec14aaf2p-6, -0x1.ce030a686bd86p-60,
	0x1.ef00000000000p-1, 0x1.149e3e4005a8dp-5, -0x1.53482d1f9d7d7p-61,
	0x1.eb00000000000p-1, 0x1.5715c4c03ceefp-5, -0x1.bbf88ec501b56p-61,
	0x1.e700000000000p-1, 0x1.9a187b573de7cp-5, -0x1.727626c86b3abp-59,
	0x1.e400000000000p-1, 0x1.ccb73cdddb2ccp-5, -0x1.e48fb0500efd4p-59,
	0x1.e000000000000p-1, 0x1.08598b59e3a07p-4, -0x1.dd7009902bf32p-58,
	0x1.dd00000000000p-1, 0x1.2207b5c78549ep-4, -0x1.cc0fbce104eaap-58,
	0x1.d900000000000p-1, 0x1.4485e03dbdfadp-4, 0x1.1ba349aadbc6ep-58,
	0x1.d600000000000p-1, 0x1.5e95a4d9791cbp-4, 0x1.f38745c5c450ap-58,
	0x1.d200000000000p-1, 0x1.8197e2f40e3f0p-4, 0x1.b9f2dffbeed43p-60,
	0x1.cf00000000000p-1, 0x1.9c0c32d4d2548p-4, 0x1.fb0be3ccc1532p-59,
	0x1.cc00000000000p-1, 0x1.b6ac88dad5b1cp-4, -0x1.0057eed1ca59fp-59,
	0x1.c900000000000p-1, 0x1.d179788219364p-4, 0x1.9daf7df76ad2ap-59,
	0x1.c600000000000p-1, 0x1.ec739830a1120p-4, -0x1.a2bf991780d3fp-59,
	0x1.c200000000000p-1, 0x1.08598b59e3a07p-3, -0x1.dd7009902bf32p-57,
	0x1.bf00000000000p-1, 0x1.160c8024b27b1p-3, -0x1.2d56ff61c2bfbp-57,
	0x1.bc00000000000p-1, 0x1.23d712a49c202p-3, -0x1.6e38161051d69p-57,
	0x1.b900000000000p-1, 0x1.31b994d3a4f85p-3, -0x1.c4716bdfc0cc9p-58,
	0x1.b600000000000p-1, 0x1.3fb45a59928ccp-3, -0x1.d87e6a354d056p-57,
	0x1.b300000000000p-1, 0x1.4dc7b897bc1c8p-3, -0x1.927d47803c5f4p-57,
	0x1.b100000000000p-1, 0x1.5737cc9018cddp-3, 0x1.4f4d710fec38ep-57,
	0x1.ae00000000000p-1, 0x1.6574ebe8c133ap-3, -0x1.d34f0f4621bedp-60,
	0x1.ab00000000000p-1, 0x1.73cb9074fd14dp-3, -0x1.521a000b4cf01p-57,
	0x1.a800000000000p-1, 0x1.823c16551a3c2p-3, -0x1.1232ce70be781p-57,
	0x1.a500000000000p-1, 0x1.90c6db9fcbcd9p-3, 0x1.054473941ad99p-57,
	0x1.a300000000000p-1, 0x1.9a8778debaa38p-3, 0x1.f47dfd871f87fp-57,
	0x1.a000000000000p-1, 0x1.a93ed3c8ad9e3p-3, 0x1.bcafa9de97203p-57,
	0x1.9d00000000000p-1, 0x1.b811730b823d2p-3, 0x1.a0ee735d9f0ecp-60,
	0x1.9b00000000000p-1, 0x1.c2028ab17f9b4p-3, 0x1.f11aa3853a5f1p-57,
	0x1.9800000000000p-1, 0x1.d1037f2655e7bp-3, 0x1.60629242471a2p-57,
	0x1.9600000000000p-1, 0x1.db13db0d48940p-3, 0x1.aa11d49f96cb9p-58,
	0x1.9300000000000p-1, 0x1.ea4449f04aaf5p-3, -0x1.d33919ab94074p-57,
	0x1.9100000000000p-1, 0x1.f474b134df229p-3, -0x1.27c77ded76aadp-58,
	0x1.8e00000000000p-1, 0x1.01eae5626c691p-2, -0x1.18290bd2932e2p-59,
	0x1.8c00000000000p-1, 0x1.07138604d5862p-2, 0x1.cdb16ed4e9138p-56,
	0x1.8a00000000000p-1, 0x1.0c42d676162e3p-2, 0x1.162c79d5d11eep-58,
	0x1.8700000000000p-1, 0x1.14167ef367783p-2, 0x1.e0936abd4fa6ep-62,
	0x1.8500000000000p-1, 0x1.1956d3b9bc2fap-2, 0x1.7b9d68d50a15dp-56,
	0x1.8300000000000p-1, 0x1.1e9e1678899f4p-2, 0x1.512c3749a1e4ep-56,
	0x1.8000000000000p-1, 0x1.269621134db92p-2, 0x1.e0efadd9db02bp-56,
	0x1.7e00000000000p-1, 0x1.2bef07cdc9354p-2, -0x1.82dad7fd86088p-56,
	0x1.7c00000000000p-1, 0x1.314f1e1d35ce4p-2, -0x1.3d69909e5c3dcp-56,
	0x1.7a00000000000p-1, 0x1.36b6776be1117p-2, -0x1.324f0e883858ep-58,
	0x1.7800000000000p-1, 0x1.3c25277333184p-2, -0x1.2ad27e50a8ec6p-56,
	0x1.7500000000000p-1, 0x1.44591e0539f49p-2, -0x1.2b125247b0fa5p-56,
	0x1.7300000000000p-1, 0x1.49da7f3bcc41fp-2, -0x1.9964a168ccacap-57,
	0x1.7100000000000p-1, 0x1.4f637ebba9810p-2, -0x1.58cb3124b9245p-56,
	0x1.6f00000000000p-1, 0x1.54f431b7be1a9p-2, -0x1.aacfdbbdab914p-56,
	0x1.6d00000000000p-1, 0x1.5a8cadbbedfa1p-2, -0x1.e6c2bdfb3e037p-58,
	0x1.6b00000000000p-1, 0x1.602d08af091ecp-2, -0x1.6e8920c09b73fp-58,
	0x1.6900000000000p+0, -0x1.5ff3070a793d4p-2, 0x1.bc60efafc6f6ep-57,
	0x1.6700000000000p+0, -0x1.5a42ab0f4cfe2p-2, 0x1.8ebcb7dee9a3dp-56,
	0x1.6500000000000p+0, -0x1.548a2c3add263p-2, 0x1.819cf7e308ddbp-57,
	0x1.6300000000000p+0, -0x1.4ec973260026ap-2, 0x1.42a87d977dc5ep-56,
	0x1.6100000000000p+0, -0x1.49006804009d1p-2, 0x1.9ffc341f177dcp-57,
	0x1.5f00000000000p+0, -0x1.432ef2a04e814p-2, 0x1.29931715ac903p-56,
	0x1.5e00000000000p+0, -0x1.404308686a7e4p-2, 0x1.0bcfb6082ce6dp-56,
	0x1.5c00000000000p+0, -0x1.3a64c556945eap-2, 0x1.c68651945f97cp-57,
	0x1.5a00000000000p+0, -0x1.347dd9a987d55p-2, 0x1.4dd4c580919f8p-57,
	0x1.5800000000000p+0, -0x1.2e8e2bae11d31p-2, 0x1.8f4cdb95ebdf9p-56,
	0x1.5600000000000p+0, -0x1.2895a13de86a3p-2, -0x1.7ad24c13f040ep-56,
	0x1.5400000000000p+0, -0x1.22941fbcf7966p-2, 0x1.76f5eb09628afp-56,
	0x1.5300000000000p+0, -0x1.1f8ff9e48a2f3p-2, 0x1.c9fdf9a0c4b07p-56,
	0x1.5100000000000p+0, -0x1.1980d2dd4236fp-2, -0x1.9d3d1b0e4d147p-56,
	0x1.4f00000000000p+0, -0x1.136870293a8b0p-2, -0x1.7b66298edd24ap-56,
	0x1.4e00000000000p+0, -0x1.1058bf9ae4ad5p-2, -0x1.89fa0ab4cb31dp-58,
	0x1.4c00000000000p+0, -0x1.0a324e27390e3p-2, -0x1.7dcfde8061c03p-56,
	0x1.4a00000000000p+0, -0x1.0402594b4d041p-2, 0x1.28ec217a5022dp-57,
	0x1.4900000000000p+0, -0x1.00e6c45ad501dp-2, 0x1.cb9568ff6feadp-57,
	0x1.4700000000000p+0, -0x1.f550a564b7b37p-3, -0x1.c5f6dfd018c37p-61,
	0x1.4500000000000p+0, -0x1.e8c0252aa5a60p-3, 0x1.6e03a39bfc89bp-59,
	0x1.4400000000000p+0, -0x1.e27076e2af2e6p-3, 0x1.61578001e0162p-59,
	0x1.4200000000000p+0, -0x1.d5c216b4fbb91p-3, -0x1.6e443597e4d40p-57,
	0x1.4000000000000p+0, -0x1.c8ff7c79a9a22p-3, 0x1.4f689f8434012p-57,
	0x1.3f00000000000p+0, -0x1.c2968558c18c1p-3, 0x1.73dee38a3fb6bp-57,
	0x1.3d00000000000p+0, -0x1.b5b519e8fb5a4p-3, -0x1.ba27fdc19e1a0p-57,
	0x1.3c00000000000p+0, -0x1.af3c94e80bff3p-3, 0x1.398cff3641985p-58,
	0x1.3a00000000000p+0, -0x1.a23bc1fe2b563p-3, -0x1.93711b07a998cp-59,
	0x1.3900000000000p+0, -0x1.9bb362e7dfb83p-3, -0x1.575e31f003e0cp-57,
	0x1.3700000000000p+0, -0x1.8e928de886d41p-3, 0x1.569d851a56770p-57,
	0x1.3600000000000p+0, -0x1.87fa06520c911p-3, 0x1.bf7fdbfa08d9ap-57,
	0x1.3400000000000p+0, -0x1.7ab890210d909p-3, -0x1.be36b2d6a0608p-59,
	0x1.3300000000000p+0, -0x1.740f8f54037a5p-3, 0x1.b264062a84cdbp-58,
	0x1.3200000000000p+0, -0x1.6d60fe719d21dp-3, 0x1.caae268ecd179p-57,
	0x1.3000000000000p+0, -0x1.5ff3070a793d4p-3, 0x1.bc60efafc6f6ep-58,
	0x1.2f00000000000p+0, -0x1.59338d9982086p-3, 0x1.65d22aa8ad7cfp-58,
	0x1.2d00000000000p+0, -0x1.4ba36f39a55e5p-3, -0x1.68981bcc36756p-57,
	0x1.2c00000000000p+0, -0x1.44d2b6ccb7d1ep-3, -0x1.9f4f6543e1f88p-57,
	0x1.2b00000000000p+0, -0x1.3dfc2b0ecc62ap-3, 0x1.ab3a8e7d81017p-58,
	0x1.2900000000000p+0, -0x1.303d718e47fd3p-3, 0x1.6b9c7d96091fap-63,
	0x1.2800000000000p+0, -0x1.29552f81ff523p-3, -0x1.301771c407dbfp-57,
	0x1.2700000000000p+0, -0x1.2266f190a5acbp-3, -0x1.f547bf1809e88p-57,
	0x1.2500000000000p+0, -0x1.14785846742acp-3, -0x1.a28813e3a7f07p-57,
	0x1.2400000000000p+0, -0x1.0d77e7cd08e59p-3, -0x1.9a5dc5e9030acp-57,
	0x1.2300000000000p+0, -0x1.0671512ca596ep-3, -0x1.50c647eb86499p-58,
	0x1.2100000000000p+0, -0x1.f0a30c01162a6p-4, -0x1.85f325c5bbacdp-58,
	0x1.2000000000000p+0, -0x1.e27076e2af2e6p-4, 0x1.61578001e0162p-60,
	0x1.1f00000000000p+0, -0x1.d4313d66cb35dp-4, -0x1.790dd951d90fap-58,
	0x1.1e00000000000p+0, -0x1.c5e548f5bc743p-4, -0x1.5d617ef8161b1p-60,
	0x1.1c00000000000p+0, -0x1.a926d3a4ad563p-4, -0x1.942f48aa70ea9p-58,
	0x1.1b00000000000p+0, -0x1.9ab42462033adp-4, 0x1.2099e1c184e8ep-59,
	0x1.1a00000000000p+0, -0x1.8c345d6319b21p-4, 0x1.4a697ab3424a9p-61,
	0x1.1900000000000p+0, -0x1.7da766d7b12cdp-4, 0x1.eeedfcdd94131p-58,
	0x1.1700000000000p+0, -0x1.60658a93750c4p-4, 0x1.388458ec21b6ap-58,
	0x1.1600000000000p+0, -0x1.51b073f06183fp-4, -0x1.a49e39a1a8be4p-58,
	0x1.1500000000000p+0, -0x1.42edcbea646f0p-4, -0x1.ddd4f935996c9p-59,
	0x1.1400000000000p+0, -0x1.341d7961bd1d1p-4, 0x1.b599f227becbbp-58,
	0x1.1300000000000p+0, -0x1.253f62f0a1417p-4, 0x1.c125963fc4cfdp-62,
	0x1.1200000000000p+0, -0x1.16536eea37ae1p-4, 0x1.79da3e8c22cdap-60,
	0x1.1000000000000p+0, -0x1.f0a30c01162a6p-5, -0x1.85f325c5bbacdp-59,
	0x1.0f00000000000p+0, -0x1.d276b8adb0b52p-5, -0x1.1e3c53257fd47p-61,
	0x1.0e00000000000p+0, -0x1.b42dd711971bfp-5, 0x1.eb9759c130499p-60,
	0x1.0d00000000000p+0, -0x1.95c830ec8e3ebp-5, -0x1.f5a0e80520bf2p-59,
	0x1.0c00000000000p+0, -0x1.77458f632dcfcp-5, -0x1.18d3ca87b9296p-59,
	0x1.0b00000000000p+0, -0x1.58a5bafc8e4d5p-5, 0x1.ce55c2b4e2b72p-59,
	0x1.0a00000000000p+0, -0x1.39e87b9febd60p-5, 0x1.5bfa937f551bbp-59,
	0x1.0900000000000p+0, -0x1.1b0d98923d980p-5, 0x1.e9ae889bac481p-60,
	0x1.0800000000000p+0, -0x1.f829b0e783300p-6, -0x1.33e3f04f1ef23p-60,
	0x1.0700000000000p+0, -0x1.b9fc027af9198p-6, 0x1.0ae69229dc868p-64,
	0x1.0600000000000p+0, -0x1.7b91b07d5b11bp-6, 0x1.5b602ace3a510p-60,
	0x1.0500000000000p+0, -0x1.3cea44346a575p-6, 0x1.0cb5a902b3a1cp-62,
	0x1.0400000000000p+0, -0x1.fc0a8b0fc03e4p-7, 0x1.83092c59642a1p-62,
	0x1.0300000000000p+0, -0x1.7dc475f810a77p-7, 0x1.16d7687d3df21p-62,
	0x1.0200000000000p+0, -0x1.fe02a6b106789p-8, 0x1.e44b7e3711ebfp-67,
	0x1.0000000000000p+0, 0x0.0p+0, 0x0.0p+0,
};
// with it, r = z invc - 1 lies in [-0.0045471191, 0.0078125]

// ---- exp, log, pow ----

// exp(r) = 1 + r + r^2 E(r) on |r| <= ln2/256 (relative error 2^-65.3)
static const double E0 = 0x1.ffffffffffdbdp-2, E1 = 0x1.555555555521ap-3, E2 = 0x1.55555cf14c204p-5,
                    E3 = 0x1.11111cddefd2bp-7;

// (h + l) 2^m for h in [1, 2), |l| < 2^-7 h, rounded once, also to a subnormal or to inf
static double scale2(double h, double l, int m) {
	if (m > 1023)
		return ((h + l) * pow2i(m - 1023)) * 0x1p1023;
	if (m > -1022) // h + l >= 0.99: normal
		return (h + l) * pow2i(m);
	// Possibly subnormal: in units of 2^-1022 the subnormal spacing is ulp(1), so adding 1 rounds
	// at the right place once; rounding h + l first and scaling would round twice.
	double sc = pow2i(m + 1022), sh = h * sc, sl = l * sc; // exact: both stay normal
	double v = sh + sl;
	if (v >= 1.0)
		return v * 0x1p-1022;
	dd a = two_sum(1.0, sh);
	return ((a.hi + (a.lo + sl)) - 1.0) * 0x1p-1022; // the subtraction and the scaling are exact
}

// exp(x + xl) for -746 <= x <= 710, xl a small tail: x = (128 m + j) ln2/128 + r,
// exp(x) = 2^m 2^(j/128) exp(r), the table entry in two parts.
static double exp_core(double x, double xl) {
	double kf = (x * INV_LN2_N + SHIFT) - SHIFT;
	int64_t k = (int64_t)kf;
	// x - kf LN2_N_HI is exact (kf < 2^18, the constant has 35 bits, and the two are close)
	double r = (x - kf * LN2_N_HI) + (xl - kf * LN2_N_LO);
	int j = (int)(k & (EXP_N - 1));
	int m = (int)((k - j) / EXP_N);
	double p = r + r * r * (E0 + r * (E1 + r * (E2 + r * E3)));
	double th = exp_tab[2 * j], tl = exp_tab[2 * j + 1];
	return scale2(th, tl + th * p, m);
}

double hs_exp(double x) {
	if (!(x <= 710.0)) // overflow (exp(709.79) is already above DBL_MAX), +inf, NaN
		return x != x ? x + x : 0x1p1023 * 0x1p1023;
	if (x < -746.0) // below half the smallest subnormal, -inf
		return 0x1p-1022 * 0x1p-1022;
	return exp_core(x, 0.0);
}

// log(1 + r) = r - r^2/2 + r^3 L(r) on -0.00455 <= r <= 0.0078126 (relative error 2^-69.5)
static const double L0 = 0x1.5555555555555p-2, L1 = -0x1.fffffffffffd0p-3, L2 = 0x1.99999999ab02bp-3,
                    L3 = -0x1.5555555f8b468p-3, L4 = 0x1.24924656b0c2ep-3, L5 = -0x1.fff5ae0385839p-4,
                    L6 = 0x1.c056090ff5da7p-4;

// log(x) as hi + lo with a relative error near 2^-68 (pow needs it), for x = the positive normal
// double with bits ix, times 2^eadj. x = 2^e z, z in [0.707, 1.414); z invc = 1 + r exactly,
// with invc of 9 bits from the table (1 around z = 1, so log(x) near 1 keeps its relative accuracy).
static dd log_dd(uint64_t ix, int eadj) {
	int e = (int)(ix >> 52) - 1023 + eadj;
	unsigned i = (unsigned)(ix >> 45) & 127u;
	uint64_t mb = ix & MANT_MASK;
	if (i >= 53) { // z >= sqrt 2: halve it
		mb |= (uint64_t)0x3fe << 52;
		e++;
	} else {
		mb |= (uint64_t)0x3ff << 52;
	}
	double z = from_bits(mb), zh = from_bits(mb & ~(uint64_t)0x1ff), zl = z - zh; // zh: 44 bits
	double invc = log_tab[3 * i];
	dd r = two_sum(zh * invc - 1.0, zl * invc); // products exact, subtraction exact (Sterbenz)
	double rh = r.hi;
	dd sq = two_prod(rh, rh);
	double poly = rh * sq.hi * (L0 + rh * (L1 + rh * (L2 + rh * (L3 + rh * (L4 + rh * (L5 + rh * L6))))));
	double ef = (double)e;
	dd a = two_sum(ef * LN2_HI, log_tab[3 * i + 1]); // ef LN2_HI exact (42-bit constant)
	dd b = two_sum(a.hi, rh);
	dd c = two_sum(b.hi, -0.5 * sq.hi);
	// log(1 + rh + rl) ~ log(1 + rh) + rl (1 - rh)
	double tail = (r.lo - rh * r.lo) - 0.5 * sq.lo + poly;
	double lo = ((ef * LN2_LO + log_tab[3 * i + 2]) + (a.lo + b.lo + c.lo)) + tail;
	return fast_two_sum(c.hi, lo);
}

double hs_log(double x) {
	uint64_t ix = bits_of(x);
	int eadj = 0;
	if (!(x > 0.0) || x == INFINITY) {
		if (x == 0.0)
			return -INFINITY;
		return x == INFINITY ? x : (x - x) / (x - x); // NaN for x < 0, -inf, NaN
	}
	if (ix < (1ULL << 52)) { // subnormal: scale into the normal range
		ix = bits_of(x * 0x1p52);
		eadj = -52;
	}
	dd l = log_dd(ix, eadj);
	return l.hi + l.lo;
}

// 0 if y is not an integer, 1 if odd, 2 if even
static int int_kind(double y) {
	double ay = fabs(y);
	if (ay >= 0x1p53)
		return 2;
	if (floor(ay) != ay)
		return 0;
	return floor(0.5 * ay) == 0.5 * ay ? 2 : 1;
}

// pow for x > 0 finite, x != 1, y finite nonzero: exp(y log x) with log x to ~2^-68 and
// y log x carried as hi + lo into exp.
static double pow_pos(double x, double y) {
	uint64_t ix = bits_of(x);
	int eadj = 0;
	if (fabs(y) > 0x1p64) // |y log x| > 2^10: overflow or underflow
		return (x > 1.0) == (y > 0) ? 0x1p1023 * 0x1p1023 : 0x1p-1022 * 0x1p-1022;
	if (ix < (1ULL << 52)) {
		ix = bits_of(x * 0x1p52);
		eadj = -52;
	}
	dd l = log_dd(ix, eadj);
	dd t = two_prod(y, l.hi);
	if (t.hi > 710.0)
		return 0x1p1023 * 0x1p1023;
	if (t.hi < -746.0)
		return 0x1p-1022 * 0x1p-1022;
	return exp_core(t.hi, t.lo + y * l.lo);
}

// pow's special operands as in C99 Annex F (zeros, infinities, NaN, negative bases)
double hs_pow(double x, double y) {
	if (y == 0.0 || x == 1.0)
		return 1.0; // even for a NaN in the other operand
	if (x != x || y != y)
		return x + y;
	if (fabs(y) == INFINITY) {
		double ax = fabs(x);
		if (ax == 1.0)
			return 1.0;
		return (ax < 1.0) == (y < 0) ? INFINITY : 0.0;
	}
	int kind = int_kind(y);
	if (x == 0.0) {
		if (y < 0)
			return kind == 1 ? 1.0 / x : INFINITY; // 1/x: ±inf with x's sign
		return kind == 1 ? x : 0.0;
	}
	if (fabs(x) == INFINITY) {
		int neg = x < 0 && kind == 1;
		if (y < 0)
			return neg ? -0.0 : 0.0;
		return neg ? -INFINITY : INFINITY;
	}
	if (x < 0) {
		if (kind == 0)
			return (x - x) / (x - x); // NaN: negative base, non-integer power
		double v = pow_pos(-x, y);
		return kind == 1 ? -v : v;
	}
	return pow_pos(x, y);
}

// ---- cbrt ----

// cbrt(m) ~ P(m) on [1, 2) to 2^-13.7, refined by one Halley step and one Newton step whose
// residual is computed exactly
static const double CB0 = 0x1.1b0baba805dccp-1, CB1 = 0x1.2c9a3edb84560p-1, CB2 = -0x1.4dc30bbe4d2a7p-3,
                    CB3 = 0x1.7a8d3f3ebaa9ep-6;

double hs_cbrt(double x) {
	static const double cbrt2k[3] = {1.0, 0x1.428a2f98d728bp+0, 0x1.965fea53d6e3dp+0}; // 2^(k/3)
	if (!(fabs(x) < INFINITY) || x == 0.0)
		return x + x; // NaN, ±inf, ±0
	uint64_t ix = bits_of(fabs(x));
	int eadj = 0;
	if (ix < (1ULL << 52)) {
		ix = bits_of(fabs(x) * 0x1p54);
		eadj = -54;
	}
	int e = (int)(ix >> 52) - 1023 + eadj;
	int q = e >= 0 ? e / 3 : -((2 - e) / 3); // floor(e / 3)
	int rem = e - 3 * q;
	double m = from_bits((ix & MANT_MASK) | ((uint64_t)0x3ff << 52));
	double u = m * (double)(1 << rem); // in [1, 8), exact
	double y = (CB0 + m * (CB1 + m * (CB2 + m * CB3))) * cbrt2k[rem];
	double y3 = y * y * y;
	y = y * ((y3 + 2.0 * u) / (2.0 * y3 + u)); // Halley: 2^-13 -> 2^-40
	dd a = two_prod(y, y), c = two_prod(y, a.hi);
	double res = ((u - c.hi) - c.lo) - y * a.lo; // u - y^3, nearly exact
	y = y + res / (3.0 * a.hi);
	double v = y * pow2i(q);
	return x < 0 ? -v : v;
}
