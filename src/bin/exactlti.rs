fn main() {
    println!("exactlti");
}
