//! Closing the holes that dropped elements leave in arrays written in place by runs of
//! threads (the soups of both builds: degenerate triangles and tetrahedra).

/// Moves the kept elements of `v` (`width` entries each) and of `per` (one entry each, or
/// empty) down over the holes of `dropped` (input ids, increasing), and returns each kept
/// element's input id. Gives memory back when much was dropped.
pub(crate) fn close_holes<T: Copy>(
    v: &mut Vec<u32>, width: usize, per: &mut Vec<T>, dropped: &[u32],
) -> crate::error::Result<Vec<u32>> {
    let n = v.len() / width;
    let mut origin =
        crate::util::alloc::try_with_capacity(n - dropped.len(), "the map to input elements")?;
    let mut next_dropped = dropped.iter().copied().peekable();
    for t in 0..n {
        if next_dropped.peek() == Some(&(t as u32)) {
            next_dropped.next();
            continue;
        }
        let kept = origin.len();
        v.copy_within(width * t..width * (t + 1), width * kept);
        if !per.is_empty() {
            per[kept] = per[t];
        }
        origin.push(t as u32);
    }
    let kept = origin.len();
    v.truncate(width * kept);
    per.truncate(if per.is_empty() { 0 } else { kept });
    if kept < n - n / 16 {
        // The structure keeps `v` for good.
        v.shrink_to_fit();
    }
    Ok(origin)
}

#[cfg(test)]
mod tests {
    #[test]
    fn kept_elements_move_down_in_order() {
        let mut v: Vec<u32> = (0..12).collect();
        let mut per = vec![10i8, 11, 12, 13];
        let origin = super::close_holes(&mut v, 3, &mut per, &[0, 2]).unwrap();
        assert_eq!(
            (v, per, origin),
            (vec![3, 4, 5, 9, 10, 11], vec![11, 13], vec![1, 3])
        );
        let mut v: Vec<u32> = (0..8).collect();
        let origin = super::close_holes(&mut v, 4, &mut Vec::<i8>::new(), &[1]).unwrap();
        assert_eq!((v, origin), (vec![0, 1, 2, 3], vec![0]));
    }
}
