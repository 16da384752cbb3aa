//! Reading lavapipe's targets back: copying a texture into a mappable
//! buffer, dropping the rows' padding, decoding f32 and f16 texels, and
//! writing the counts and channel groups into a [`Frame`], checked.

use crate::frame::Frame;
use crate::rasterizer::RasterError;

/// Records a copy of a `width × height` texture of `texel`-byte texels into
/// a mappable buffer; returns the buffer and its padded row length.
pub(super) fn copy_out(
    device: &wgpu::Device,
    encoder: &mut wgpu::CommandEncoder,
    texture: &wgpu::Texture,
    texel: u32,
    (width, height): (u32, u32),
) -> (wgpu::Buffer, u32) {
    let row = (width * texel).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback"),
        size: u64::from(row) * u64::from(height),
        usage: wgpu::BufferUsages::COPY_DST | wgpu::BufferUsages::MAP_READ,
        mapped_at_creation: false,
    });
    encoder.copy_texture_to_buffer(
        wgpu::TexelCopyTextureInfo {
            texture,
            mip_level: 0,
            origin: wgpu::Origin3d::ZERO,
            aspect: wgpu::TextureAspect::All,
        },
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(row),
                rows_per_image: Some(height),
            },
        },
        wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
    );
    (buffer, row)
}

/// The rows of a mapped readback buffer without their padding.
pub(super) fn read_rows(
    (buffer, row): &(wgpu::Buffer, u32),
    texel: usize,
    (width, height): (u32, u32),
) -> Result<Vec<u8>, RasterError> {
    let view = buffer
        .get_mapped_range(..)
        .map_err(|e| RasterError::Failed(format!("lavapipe: reading back: {e}")))?;
    let mut out = Vec::with_capacity(width as usize * height as usize * texel);
    for y in 0..height as usize {
        let start = y * *row as usize;
        out.extend_from_slice(&view[start..start + width as usize * texel]);
    }
    Ok(out)
}

pub(super) fn floats(bytes: &[u8]) -> Vec<f32> {
    bytes
        .chunks_exact(4)
        .map(|b| f32::from_le_bytes([b[0], b[1], b[2], b[3]]))
        .collect()
}

/// IEEE binary16 to f32 (the count target where f32 blending is missing).
fn f16_to_f32(bits: u16) -> f32 {
    let sign = if bits & 0x8000 != 0 { -1.0 } else { 1.0 };
    let exponent = i32::from((bits >> 10) & 0x1f);
    let mantissa = f32::from(bits & 0x3ff);
    sign * match exponent {
        0 => mantissa * 2f32.powi(-24),
        31 => f32::INFINITY,
        e => (1.0 + mantissa / 1024.0) * 2f32.powi(e - 15),
    }
}

/// The coverage counts of a count target read back in `format`:
/// `R32Float`, or `R16Float` where f32 blending is missing.
pub(super) fn counts(bytes: &[u8], format: wgpu::TextureFormat) -> Vec<f32> {
    if format == wgpu::TextureFormat::R32Float {
        floats(bytes)
    } else {
        bytes
            .chunks_exact(2)
            .map(|b| f16_to_f32(u16::from_le_bytes([b[0], b[1]])))
            .collect()
    }
}

/// The channels `[primitive + 1, depth, attribute 0, …]` of the mapped
/// channel-group buffers (four f32 channels each), slot by slot.
pub(super) fn channels(
    buffers: &[(wgpu::Buffer, u32)],
    size: (u32, u32),
) -> Result<Vec<Vec<f32>>, RasterError> {
    let n = size.0 as usize * size.1 as usize;
    let mut channels: Vec<Vec<f32>> = vec![Vec::with_capacity(n); buffers.len() * 4];
    for (g, buffer) in buffers.iter().enumerate() {
        for (k, v) in floats(&read_rows(buffer, 16, size)?)
            .into_iter()
            .enumerate()
        {
            channels[g * 4 + k % 4].push(v);
        }
    }
    Ok(channels)
}

/// Writes the counts and channels read back into `frame`, slot by slot:
/// the count, the last primitive, and where covered the depth and
/// attributes. A count that is not a whole number of covers is an error
/// naming the `unit` it was read at ("sample", "slot"); `saturated` says
/// why a count is beyond what its format holds exactly, if it is.
pub(super) fn fill(
    frame: &mut Frame,
    counts: &[f32],
    channels: &[Vec<f32>],
    unit: &str,
    saturated: impl Fn(f32) -> Option<String>,
) -> Result<(), RasterError> {
    for (i, &c) in counts.iter().enumerate() {
        if c.fract() != 0.0 || !(0.0..=65535.0).contains(&c) {
            return Err(RasterError::Failed(format!(
                "lavapipe: coverage count {c} read back at {unit} {i}"
            )));
        }
        if let Some(why) = saturated(c) {
            return Err(RasterError::Failed(why));
        }
        frame.coverage[i] = c as u16;
        frame.last[i] = channels[0][i] as u32;
        if c > 0.0 {
            if let Some(depth) = &mut frame.depth {
                depth[i] = f64::from(channels[1][i]);
            }
            for (k, a) in frame.attributes.iter_mut().enumerate() {
                a[i] = f64::from(channels[2 + k][i]);
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_floats_decode() {
        assert_eq!(f16_to_f32(0x0000), 0.0);
        assert_eq!(f16_to_f32(0x3c00), 1.0);
        assert_eq!(f16_to_f32(0x4000), 2.0);
        assert_eq!(f16_to_f32(0x6800), 2048.0);
    }
}
