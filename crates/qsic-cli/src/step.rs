//! ISO 10303-21 (STEP) text of NURBS curves: an AP214 part whose shape is a
//! `GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION` holding one `GEOMETRIC_CURVE_SET`
//! of `B_SPLINE_CURVE_WITH_KNOTS`, as the complex entity with `RATIONAL_B_SPLINE_CURVE` where
//! the weights are not all equal, control points as `CARTESIAN_POINT`s. A string writer: the
//! caller writes the file.

/// One curve as STEP takes it: floats (the exact data rounded once, to the nearest double).
#[derive(Clone, Debug, PartialEq)]
pub struct StepCurve {
    /// The degree.
    pub degree: usize,
    /// The control points in ℝ³.
    pub points: Vec<[f64; 3]>,
    /// The weights (positive), one a point.
    pub weights: Vec<f64>,
    /// The distinct knots.
    pub knots: Vec<f64>,
    /// Their multiplicities.
    pub multiplicities: Vec<usize>,
}

/// A STEP real: the shortest text that reads back as `v`, with the decimal point the
/// grammar requires (`1.`, `-2.5`, `1.E-07`).
pub fn real(v: f64) -> String {
    let v = if v == 0.0 { 0.0 } else { v };
    let s = format!("{v:?}");
    let (mantissa, exponent) = match s.split_once('e') {
        Some((m, e)) => (m.to_string(), Some(e.to_string())),
        None => (s, None),
    };
    let mantissa = if mantissa.contains('.') {
        mantissa.trim_end_matches('0').to_string()
    } else {
        format!("{mantissa}.")
    };
    match exponent {
        Some(e) => format!("{mantissa}E{e}"),
        None => mantissa,
    }
}

/// A STEP string literal (apostrophes doubled; non-ASCII replaced: the text is ASCII).
fn string(s: &str) -> String {
    let mut out = String::from("'");
    for c in s.chars() {
        match c {
            '\'' => out.push_str("''"),
            '\\' => out.push_str("\\\\"),
            c if c.is_ascii() && !c.is_ascii_control() => out.push(c),
            _ => out.push('?'),
        }
    }
    out.push('\'');
    out
}

/// The whole STEP file of `curves`, named `name` (its `FILE_NAME` and product).
pub fn step_text(curves: &[StepCurve], name: &str, description: &str) -> String {
    let mut data: Vec<String> = Vec::new();
    let mut add = |text: String| -> usize {
        data.push(text);
        data.len()
    };
    let app = add("APPLICATION_CONTEXT('automotive design')".into());
    add(format!(
        "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,#{app})"
    ));
    let pc = add(format!("PRODUCT_CONTEXT('',#{app},'mechanical')"));
    let product = add(format!("PRODUCT({n},{n},'',(#{pc}))", n = string(name)));
    let formation = add(format!("PRODUCT_DEFINITION_FORMATION('','',#{product})"));
    let pdc = add(format!(
        "PRODUCT_DEFINITION_CONTEXT('part definition',#{app},'design')"
    ));
    let pd = add(format!(
        "PRODUCT_DEFINITION('design','',#{formation},#{pdc})"
    ));
    let pds = add(format!("PRODUCT_DEFINITION_SHAPE('','',#{pd})"));
    let length = add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) )".into());
    let angle = add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )".into());
    let solid = add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )".into());
    let uncertainty = add(format!(
        "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),#{length},'distance_accuracy_value','')"
    ));
    let context = add(format!(
        "( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((#{uncertainty})) \
         GLOBAL_UNIT_ASSIGNED_CONTEXT((#{length},#{angle},#{solid})) REPRESENTATION_CONTEXT('','3D') )"
    ));
    let mut items = Vec::new();
    for (k, c) in curves.iter().enumerate() {
        let points: Vec<String> = c
            .points
            .iter()
            .map(|p| {
                let id = add(format!(
                    "CARTESIAN_POINT('',({},{},{}))",
                    real(p[0]),
                    real(p[1]),
                    real(p[2])
                ));
                format!("#{id}")
            })
            .collect();
        let list = |v: Vec<String>| v.join(",");
        let points = list(points);
        let mults = list(c.multiplicities.iter().map(usize::to_string).collect());
        let knots = list(c.knots.iter().map(|v| real(*v)).collect());
        let rational = c.weights.windows(2).any(|w| w[0] != w[1]);
        let label = string(&format!("curve {k}"));
        let id = if rational {
            let weights = list(c.weights.iter().map(|v| real(*v)).collect());
            add(format!(
                "( BOUNDED_CURVE() B_SPLINE_CURVE({},({points}),.UNSPECIFIED.,.F.,.F.) \
                 B_SPLINE_CURVE_WITH_KNOTS(({mults}),({knots}),.UNSPECIFIED.) CURVE() \
                 GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE(({weights})) \
                 REPRESENTATION_ITEM({label}) )",
                c.degree
            ))
        } else {
            add(format!(
                "B_SPLINE_CURVE_WITH_KNOTS({label},{},({points}),.UNSPECIFIED.,.F.,.F.,({mults}),({knots}),.UNSPECIFIED.)",
                c.degree
            ))
        };
        items.push(format!("#{id}"));
    }
    let set = add(format!("GEOMETRIC_CURVE_SET('',({}))", items.join(",")));
    let rep = add(format!(
        "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('',(#{set}),#{context})"
    ));
    add(format!("SHAPE_DEFINITION_REPRESENTATION(#{pds},#{rep})"));
    let mut out = String::from("ISO-10303-21;\nHEADER;\n");
    out.push_str(&format!(
        "FILE_DESCRIPTION(({}),'2;1');\n",
        string(description)
    ));
    out.push_str(&format!(
        "FILE_NAME({},'',(''),(''),'qsic','qsic','');\n",
        string(name)
    ));
    out.push_str("FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n");
    for (i, d) in data.iter().enumerate() {
        out.push_str(&format!("#{} = {d};\n", i + 1));
    }
    out.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_have_a_decimal_point_and_read_back() {
        for v in [1.0, -2.5, 1e-7, 0.1, 3.0e20, 0.0, -0.0, 123456.789] {
            let s = real(v);
            assert!(s.contains('.'), "{s}");
            assert!(!s.contains('e'), "{s}");
            let back: f64 = s.replace('E', "e").parse().unwrap();
            assert_eq!(back, v, "{s}");
        }
    }

    #[test]
    fn rational_curves_are_complex_entities() {
        let c = StepCurve {
            degree: 2,
            points: vec![[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]],
            weights: vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
            knots: vec![0.0, 1.0],
            multiplicities: vec![3, 3],
        };
        let text = step_text(std::slice::from_ref(&c), "q'1", "test");
        assert!(
            text.contains("RATIONAL_B_SPLINE_CURVE((1.,0.7071067811865476,1.))"),
            "{text}"
        );
        assert!(text.contains("B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.,1.),.UNSPECIFIED.)"));
        assert!(text.contains("'q''1'"));
        assert_eq!(text.matches("CARTESIAN_POINT").count(), 3);
        let plain = StepCurve {
            weights: vec![2.0; 3],
            ..c
        };
        let text = step_text(&[plain], "p", "test");
        assert!(!text.contains("RATIONAL"));
        assert!(text.contains("B_SPLINE_CURVE_WITH_KNOTS('curve 0',2,"));
    }
}
