//! Laying pieces out on stock boards or sheets: a deterministic first-fit-decreasing shelf
//! packing. Pieces are taken longest first (ties in their given order); each goes to the first
//! shelf of the first board with room for it, else a new shelf on the first board with room for
//! one, else a new board. Shelves are as high as their first (tallest-so-far) piece.

/// Where a piece lies: its board (from 0) and the lower-left corner of its bounding box on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placement {
    pub board: usize,
    pub position: [f64; 2],
}

struct Shelf {
    bottom: f64,
    height: f64,
    /// Length used so far, including the gaps.
    used: f64,
}

/// Packs boxes of `sizes` (length along the board, height across it) onto boards of `board`
/// size with `gap` between neighbours. Every box must fit a board (checked by the caller).
/// Returns one placement per box and the number of boards.
pub fn pack(sizes: &[[f64; 2]], board: [f64; 2], gap: f64) -> (Vec<Placement>, usize) {
    let mut order: Vec<usize> = (0..sizes.len()).collect();
    order.sort_by(|&a, &b| sizes[b][0].total_cmp(&sizes[a][0]).then(a.cmp(&b)));
    let mut boards: Vec<Vec<Shelf>> = Vec::new();
    let mut placements = vec![Placement { board: 0, position: [0.0, 0.0] }; sizes.len()];
    for index in order {
        let [length, height] = sizes[index];
        let on_shelf = boards.iter_mut().enumerate().find_map(|(b, shelves)| {
            let shelf = shelves.iter_mut().find(|s| height <= s.height && s.used + gap + length <= board[0])?;
            let x = shelf.used + gap;
            shelf.used = x + length;
            Some(Placement { board: b, position: [x, shelf.bottom] })
        });
        let placement = on_shelf.unwrap_or_else(|| {
            let top = |shelves: &Vec<Shelf>| shelves.last().map_or(0.0, |s| s.bottom + s.height + gap);
            let b = boards.iter().position(|shelves| top(shelves) + height <= board[1]).unwrap_or_else(|| {
                boards.push(Vec::new());
                boards.len() - 1
            });
            let bottom = top(&boards[b]);
            boards[b].push(Shelf { bottom, height, used: length });
            Placement { board: b, position: [0.0, bottom] }
        });
        placements[index] = placement;
    }
    (placements, boards.len())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_fit_decreasing_fills_boards_in_order() {
        let sizes = [[2.0, 0.3], [4.0, 0.3], [3.0, 0.3], [0.7, 0.3]];
        let (placed, boards) = pack(&sizes, [4.8, 0.3], 0.01);
        assert_eq!(boards, 3);
        assert_eq!(placed[1], Placement { board: 0, position: [0.0, 0.0] });
        assert_eq!(placed[2], Placement { board: 1, position: [0.0, 0.0] });
        assert_eq!(placed[0], Placement { board: 2, position: [0.0, 0.0] });
        // 0.7 m fits after the 4 m piece (4.01 + 0.7 ≤ 4.8).
        assert_eq!(placed[3].board, 0);
        assert!((placed[3].position[0] - 4.01).abs() < 1e-12);
    }
}
