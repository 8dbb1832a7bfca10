//! ISO 25178-72 `.x3p` files (the XML 3D surface profile exchange format of OpenGPS): a zip
//! archive holding `main.xml`, which describes the axes and the matrix, and the binary heights
//! it links, usually `bindata/data.bin`.
//!
//! Read here: a surface (`FeatureType` `SUR`) with incremental x and y axes
//! (`Record1/Axes/CX|CY/AxisType` `I`, spacing `Increment` in m) and heights along z of data
//! type `I` (16-bit), `L` (32-bit integer), `F` (32-bit float) or `D` (64-bit float),
//! little-endian, x running fastest, then y (`Record3/MatrixDimension/SizeX|SizeY`, `SizeZ`
//! 1). Heights are `raw · Increment + Offset` of `CZ` (in m; both optional, 1 and 0). The MD5
//! checksum of the binary data given in `Record3/DataLink/MD5ChecksumPointData` is checked, and
//! the one of `main.xml` in `md5checksum.hex` when the archive has it. Missing points are NaN
//! (float types), refused or filled as the caller asks; a separate valid-points bit array
//! (`ValidPointsLink`) is not supported and refused with a message.
//!
//! ## References
//! - ISO 25178-72:2017, Geometrical product specifications (GPS) — Surface texture: Areal —
//!   Part 72: XML file format x3p.
//! - ISO 5436-2:2012 (the `ISO5436_2` XML schema of the format, published by OpenGPS).

use std::path::Path;

use md5::{Digest, Md5};
use ndarray::Array2;

use super::samples::{interpolate_missing, Fill, ReadError};
use super::HeightMap;
use crate::io::archive::{Archive, ArchiveError, Limit};
use crate::io::text::cut;

fn format(path: &str, message: impl Into<String>) -> ReadError {
    ReadError::Format {
        path: path.to_string(),
        message: message.into(),
    }
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

/// The largest `main.xml`: it describes the axes and the matrix in a few KiB (the heights are
/// in the binary member it links).
const MAIN_XML_LIMIT: u64 = 16 << 20;

/// Reads an `.x3p` file (module doc); no file of the archive may exceed `size_limit` bytes.
pub fn read(path: &Path, size_limit: u64, fill: Fill) -> Result<HeightMap, ReadError> {
    let name = path.display().to_string();
    let file = std::fs::File::open(path).map_err(|source| ReadError::Io {
        path: name.clone(),
        source,
    })?;
    // A directory opens as a file here; the zip reader would then say "not a zip archive
    // (i/o error)" (issue 42, a leftover of round two).
    if file.metadata().is_ok_and(|m| m.is_dir()) {
        return Err(ReadError::Io {
            path: name,
            source: std::io::Error::other("it is a directory, not an .x3p file"),
        });
    }
    let size = file.metadata().map(|m| m.len()).unwrap_or(0);
    if size > size_limit {
        return Err(ReadError::TooLarge {
            path: name,
            size_mib: size >> 20,
            limit_mib: size_limit >> 20,
            needed_mib: (size * 4) >> 20,
        });
    }
    let mut archive = Archive::new(file, &name)?;
    let xml = archive.member(
        "main.xml",
        Limit::AtMost(
            MAIN_XML_LIMIT.min(size_limit),
            "main.xml describes the axes and the matrix in a few KiB",
        ),
    )?;
    match archive.member(
        "md5checksum.hex",
        Limit::AtMost(4096, "md5checksum.hex holds one checksum line"),
    ) {
        Err(ArchiveError::Missing { .. }) => {}
        Err(other) => return Err(other.into()),
        Ok(listed) => {
            let text = String::from_utf8_lossy(&listed);
            let expected = text
                .split_whitespace()
                .next()
                .unwrap_or("")
                .to_ascii_lowercase();
            let actual = hex(&Md5::digest(&xml));
            if expected != actual {
                return Err(format(
                    &name,
                    format!("the MD5 checksum of main.xml is {actual}, md5checksum.hex says {}: the file is damaged", cut(&expected, 40)),
                ));
            }
        }
    }
    let text =
        std::str::from_utf8(&xml).map_err(|_| format(&name, "main.xml is not UTF-8 text"))?;
    let document = roxmltree::Document::parse(text)
        .map_err(|e| format(&name, format!("main.xml is not well-formed XML: {e}")))?;
    // Elements are found by their local name (the root carries the ISO5436_2 namespace, the
    // records none).
    let find = |path: &[&str]| -> Option<String> {
        let mut node = document.root_element();
        for step in path {
            node = node
                .children()
                .find(|n| n.is_element() && n.tag_name().name() == *step)?;
        }
        Some(node.text().unwrap_or("").trim().to_string())
    };
    let need = |path: &[&str]| {
        find(path).ok_or_else(|| format(&name, format!("main.xml has no {}", path.join("/"))))
    };
    // A number of main.xml: finite, or an error naming its key (an overflowing `1e400` is no
    // number, not a missing point).
    let number = |path: &[&str]| -> Result<f64, ReadError> {
        let text = need(path)?;
        match text.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            Ok(_) => Err(format(
                &name,
                format!(
                    "{} = `{}` is not a finite number; write the value in range (at most 1.8e308 in size)",
                    path.join("/"),
                    cut(&text, 40)
                ),
            )),
            Err(_) => Err(format(
                &name,
                format!("{} = `{}` is not a number", path.join("/"), cut(&text, 40)),
            )),
        }
    };
    if let Some(kind) = find(&["Record1", "FeatureType"]) {
        if kind != "SUR" {
            return Err(format(
                &name,
                format!(
                    "the file holds a `{}` feature; only areal surfaces (SUR) are read",
                    cut(&kind, 40)
                ),
            ));
        }
    }
    for axis in ["CX", "CY"] {
        let kind = need(&["Record1", "Axes", axis, "AxisType"])?;
        if kind != "I" {
            return Err(format(
                &name,
                format!(
                    "the {axis} axis is `{}`; only incremental x and y axes (I) are read",
                    cut(&kind, 40)
                ),
            ));
        }
    }
    let dx = number(&["Record1", "Axes", "CX", "Increment"])?;
    let dy = number(&["Record1", "Axes", "CY", "Increment"])?;
    let data_type = need(&["Record1", "Axes", "CZ", "DataType"])?;
    let z_increment = match find(&["Record1", "Axes", "CZ", "Increment"]) {
        Some(t) if !t.is_empty() => number(&["Record1", "Axes", "CZ", "Increment"])?,
        _ => 1.0,
    };
    if z_increment == 0.0 {
        return Err(format(
            &name,
            "Record1/Axes/CZ/Increment is 0, which makes every height equal; give the z resolution in m (e.g. 1e-9), or leave the key out for 1",
        ));
    }
    let z_offset = match find(&["Record1", "Axes", "CZ", "Offset"]) {
        Some(t) if !t.is_empty() => number(&["Record1", "Axes", "CZ", "Offset"])?,
        _ => 0.0,
    };
    let size = |axis: &str| -> Result<usize, ReadError> {
        let value = number(&["Record3", "MatrixDimension", axis])?;
        if value >= 0.0 && value.fract() == 0.0 && value < 1e9 {
            Ok(value as usize)
        } else {
            Err(format(
                &name,
                format!("Record3/MatrixDimension/{axis} = {value} is not a count"),
            ))
        }
    };
    let (nx, ny, nz) = (size("SizeX")?, size("SizeY")?, size("SizeZ")?);
    if nz != 1 {
        return Err(format(
            &name,
            format!("SizeZ is {nz}; only one layer of heights is read"),
        ));
    }
    if find(&["Record3", "DataLink", "ValidPointsLink"]).is_some() {
        return Err(format(
            &name,
            "the file marks invalid points in a separate bit array (ValidPointsLink), which is not supported; export it with NaN for missing points (data type F or D)",
        ));
    }
    let width: u64 = match data_type.as_str() {
        "I" => 2,
        "L" | "F" => 4,
        "D" => 8,
        other => {
            return Err(format(
                &name,
                format!(
                    "unknown data type `{}` of CZ; x3p uses I, L, F or D",
                    cut(other, 40)
                ),
            ))
        }
    };
    // The binary data main.xml describes, checked against the limit before it is unpacked (at
    // most 1e18 bytes: no overflow).
    let expected = nx as u64 * ny as u64 * width;
    if expected > size_limit {
        return Err(format(
            &name,
            format!(
                "main.xml describes {nx} x {ny} values of type {data_type}, {}, more than the {} a surface file may have here (its heights would need {} more); crop or resample the surface",
                crate::io::text::bytes(expected),
                crate::io::text::bytes(size_limit),
                crate::io::text::bytes(nx as u64 * ny as u64 * 8)
            ),
        ));
    }
    // Every surface read is characterised: a map this machine cannot characterise is refused
    // before its heights are unpacked.
    super::stats::check_memory([ny, nx], crate::field::memory_limit_bytes() as u64)
        .map_err(|e| format(&name, e.to_string()))?;
    let link = need(&["Record3", "DataLink", "PointDataLink"])?;
    let why = format!("main.xml's {nx} x {ny} values of type {data_type}");
    let data = archive.member(&link, Limit::Exactly(expected, &why))?;
    if let Some(expected) = find(&["Record3", "DataLink", "MD5ChecksumPointData"]) {
        let actual = hex(&Md5::digest(&data));
        if !expected.is_empty() && expected.to_ascii_lowercase() != actual {
            return Err(format(
                &name,
                format!(
                    "the MD5 checksum of {} is {actual}, main.xml says {}: the file is damaged",
                    cut(&link, 80),
                    cut(&expected, 40)
                ),
            ));
        }
    }
    let width = width as usize;
    let raw = |k: usize| -> f64 {
        let b = &data[k * width..(k + 1) * width];
        match width {
            2 => f64::from(i16::from_le_bytes([b[0], b[1]])),
            4 if data_type == "L" => f64::from(i32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            4 => f64::from(f32::from_le_bytes([b[0], b[1], b[2], b[3]])),
            _ => f64::from_le_bytes([b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7]]),
        }
    };
    let mut heights =
        Array2::from_shape_fn((ny, nx), |(j, i)| raw(j * nx + i) * z_increment + z_offset);
    // A finite raw value whose height overflows is the increment's or offset's fault, not a
    // missing point.
    if let Some(((row, column), _)) = heights
        .indexed_iter()
        .find(|((j, i), v)| !v.is_finite() && raw(j * nx + i).is_finite())
    {
        return Err(format(
            &name,
            format!(
                "row {row}, column {column}: the raw value {} times Record1/Axes/CZ/Increment = {} plus Offset = {} is out of range; give the z increment in m (e.g. 1e-9)",
                crate::io::text::number(raw(row * nx + column)),
                crate::io::text::number(z_increment),
                crate::io::text::number(z_offset)
            ),
        ));
    }
    if let Some(((row, column), _)) = heights.indexed_iter().find(|(_, v)| !v.is_finite()) {
        match fill {
            Fill::Refuse => {
                let count = heights.iter().filter(|v| !v.is_finite()).count();
                return Err(format(
                    &name,
                    format!("row {row}, column {column} is missing ({count} missing point(s) in all); fill them with fill = \"interpolate\" (--fill interpolate)"),
                ));
            }
            Fill::Interpolate => interpolate_missing(&mut heights).map_err(|m| format(&name, m))?,
        }
    }
    HeightMap::new(heights, [dx, dy]).map_err(|source| ReadError::Surface { path: name, source })
}

/// Writes a surface as an `.x3p` archive (data type D), the layout [`read`] takes; used by the
/// tests and to export generated surfaces.
pub fn write(map: &HeightMap) -> Result<Vec<u8>, String> {
    use std::io::Write;
    let [ny, nx] = map.shape();
    let [dx, dy] = map.spacing_m();
    let mut data = Vec::with_capacity(nx * ny * 8);
    for value in map.heights_m().iter() {
        data.extend_from_slice(&value.to_le_bytes());
    }
    let xml = format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1>
    <Revision>ISO5436 - 2000</Revision>
    <FeatureType>SUR</FeatureType>
    <Axes>
      <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{dx:e}</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{dy:e}</Increment><Offset>0</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>D</DataType></CZ>
    </Axes>
  </Record1>
  <Record2>
    <Date>2026-01-01T00:00:00+00:00</Date>
    <Instrument><Manufacturer>stressfield</Manufacturer><Model>generator</Model><Serial>0</Serial><Version>1</Version></Instrument>
    <CalibrationDate>2026-01-01T00:00:00+00:00</CalibrationDate>
    <ProbingSystem><Type>NonContacting</Type><Identification>none</Identification></ProbingSystem>
    <Comment>written by stressfield</Comment>
  </Record2>
  <Record3>
    <MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
    <DataLink><PointDataLink>bindata/data.bin</PointDataLink><MD5ChecksumPointData>{checksum}</MD5ChecksumPointData></DataLink>
  </Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
"#,
        checksum = hex(&Md5::digest(&data)),
    );
    let mut bytes = Vec::new();
    {
        let mut zip = zip::ZipWriter::new(std::io::Cursor::new(&mut bytes));
        let options = zip::write::SimpleFileOptions::default()
            .compression_method(zip::CompressionMethod::Deflated);
        let error = |e: zip::result::ZipError| e.to_string();
        zip.start_file("main.xml", options).map_err(error)?;
        zip.write_all(xml.as_bytes()).map_err(|e| e.to_string())?;
        zip.start_file("bindata/data.bin", options).map_err(error)?;
        zip.write_all(&data).map_err(|e| e.to_string())?;
        zip.start_file("md5checksum.hex", options).map_err(error)?;
        let line = format!("{} *main.xml\n", hex(&Md5::digest(xml.as_bytes())));
        zip.write_all(line.as_bytes()).map_err(|e| e.to_string())?;
        zip.finish().map_err(error)?;
    }
    Ok(bytes)
}

#[cfg(test)]
mod tests {
    use std::io::Write;

    use super::*;

    /// An x3p archive built from the standard's layout by hand: integer heights with a z
    /// increment and offset, and an explicit MD5 of the data.
    fn handmade(data_type: &str, values: &[u8], checksum: Option<&str>) -> Vec<u8> {
        handmade_with(data_type, values, checksum, "1e-9", (3, 2))
    }

    /// [`handmade`] with the z increment and the matrix size (x, y) given.
    fn handmade_with(
        data_type: &str,
        values: &[u8],
        checksum: Option<&str>,
        z_increment: &str,
        (nx, ny): (usize, usize),
    ) -> Vec<u8> {
        let sum = checksum.map_or_else(|| hex(&Md5::digest(values)), str::to_string);
        let xml = format!(
            "<?xml version=\"1.0\"?><p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\"><Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>2.5E-06</Increment><Offset>0</Offset></CX><CY><AxisType>I</AxisType><DataType>D</DataType><Increment>5E-06</Increment><Offset>0</Offset></CY><CZ><AxisType>A</AxisType><DataType>{data_type}</DataType><Increment>{z_increment}</Increment><Offset>1e-6</Offset></CZ></Axes></Record1><Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension><DataLink><PointDataLink>bindata/data.bin</PointDataLink><MD5ChecksumPointData>{sum}</MD5ChecksumPointData></DataLink></Record3></p:ISO5436_2>"
        );
        let mut bytes = Vec::new();
        {
            let mut zip = zip::ZipWriter::new(std::io::Cursor::new(&mut bytes));
            let options = zip::write::SimpleFileOptions::default();
            zip.start_file("main.xml", options).expect("entry");
            zip.write_all(xml.as_bytes()).expect("xml");
            zip.start_file("bindata/data.bin", options).expect("entry");
            zip.write_all(values).expect("data");
            zip.finish().expect("zip");
        }
        bytes
    }

    fn read_bytes(bytes: &[u8], fill: Fill) -> Result<HeightMap, ReadError> {
        let dir = tempfile::tempdir().expect("dir");
        let path = dir.path().join("s.x3p");
        std::fs::write(&path, bytes).expect("write");
        read(&path, 1 << 30, fill)
    }

    #[test]
    fn reads_integer_heights_with_increment_and_offset() {
        let values: Vec<u8> = [1i16, -2, 3, 400, 5, -600]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let map = read_bytes(&handmade("I", &values, None), Fill::Refuse).expect("valid");
        assert_eq!(map.shape(), [2, 3]);
        assert_eq!(map.spacing_m(), [2.5e-6, 5e-6]);
        // x fastest: row 1 holds 400, 5, -600.
        assert!((map.heights_m()[[1, 0]] - (400e-9 + 1e-6)).abs() < 1e-18);
        assert!((map.heights_m()[[0, 1]] - (-2e-9 + 1e-6)).abs() < 1e-18);
    }

    #[test]
    fn a_bad_checksum_or_missing_point_is_refused() {
        let values: Vec<u8> = [1i32, 2, 3, 4, 5, 6]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let error = read_bytes(
            &handmade("L", &values, Some("0123456789abcdef0123456789abcdef")),
            Fill::Refuse,
        )
        .expect_err("checksum")
        .to_string();
        assert!(
            error.contains("MD5") && error.contains("damaged"),
            "{error}"
        );
        let floats: Vec<u8> = [1f32, f32::NAN, 3.0, 4.0, 5.0, 6.0]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        let error = read_bytes(&handmade("F", &floats, None), Fill::Refuse)
            .expect_err("nan")
            .to_string();
        assert!(error.contains("row 0, column 1 is missing"), "{error}");
        let filled = read_bytes(&handmade("F", &floats, None), Fill::Interpolate).expect("filled");
        assert!(filled.heights_m()[[0, 1]].is_finite());
        let short =
            read_bytes(&handmade("D", &values[..8], None), Fill::Refuse).expect_err("short");
        assert!(short.to_string().contains("bytes"), "{short}");
        assert!(read_bytes(b"not a zip", Fill::Refuse).is_err());
    }

    #[test]
    fn written_archives_read_back_bit_for_bit() {
        let heights = Array2::from_shape_fn((4, 5), |(j, i)| (i as f64 - 2.0 * j as f64) * 1.25e-7);
        let map = HeightMap::new(heights, [1e-6, 2e-6]).expect("map");
        let bytes = write(&map).expect("write");
        assert_eq!(read_bytes(&bytes, Fill::Refuse).expect("read"), map);
    }

    /// Issue 24, class 2: a zip bomb (main.xml says 24 x 16 points, the data member inflates
    /// to 64 MiB) is refused by its declared size before it is unpacked.
    #[test]
    fn a_zip_bomb_is_refused_before_it_is_unpacked() {
        let bomb = vec![0u8; 64 << 20];
        let bytes = handmade_with("D", &bomb, Some(""), "1e-9", (24, 16));
        assert!(bytes.len() < 1 << 20, "deflated: {} bytes", bytes.len());
        let error = read_bytes(&bytes, Fill::Refuse)
            .expect_err("bomb")
            .to_string();
        assert!(
            error.contains("s.x3p: member bindata/data.bin: declares 67108864 bytes")
                && error.contains("24 x 16 values of type D take 3072 bytes"),
            "{error}"
        );
        // A matrix beyond the size limit is refused from main.xml alone.
        let dir = tempfile::tempdir().expect("dir");
        let path = dir.path().join("big.x3p");
        std::fs::write(
            &path,
            handmade_with("D", &[0; 8], None, "1e-9", (16384, 16384)),
        )
        .expect("write");
        let error = read(&path, 1 << 30, Fill::Refuse)
            .expect_err("big")
            .to_string();
        assert!(
            error.contains("16384 x 16384 values of type D, 2 GiB, more than the 1 GiB")
                && error.contains("crop or resample"),
            "{error}"
        );
    }

    /// Issue 24, class 7: an out-of-range z increment is an error naming its key, never a
    /// missing point; 0 is refused too.
    #[test]
    fn an_out_of_range_increment_names_its_key() {
        let values: Vec<u8> = [1i16, -2, 3, 400, 5, -600]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
        for (increment, fragment) in [
            (
                "NaN",
                "Record1/Axes/CZ/Increment = `NaN` is not a finite number",
            ),
            (
                "1e400",
                "Record1/Axes/CZ/Increment = `1e400` is not a finite number",
            ),
            ("1e308", "times Record1/Axes/CZ/Increment = 1e308"),
            ("0", "Record1/Axes/CZ/Increment is 0"),
        ] {
            let bytes = handmade_with("I", &values, None, increment, (3, 2));
            let error = read_bytes(&bytes, Fill::Interpolate)
                .expect_err(increment)
                .to_string();
            assert!(
                error.contains(fragment) && !error.contains("missing"),
                "{increment}: {error}"
            );
        }
    }
}
